#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <dyncontact/base/vector_copy.h>
#include <dyncontact/time_stepping/step_size_control.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace dyncontact
{
  namespace
  {
    /// The fraction of the step (of length trial.tau) at which the free
    /// row @p row (number @p p, constraint value @p before at t_n and rate
    /// (C udot^n)_p @p rate) comes into contact: where its constraint value
    /// reaches 0 if it approaches, else, if the @p trial holds it, where it
    /// reaches the penetration that the multiplier stands for (if above
    /// @p touching); 2 if neither.
    double
    contact_fraction(const StepOperators &operators,
                     const ContactRow    &row,
                     const StepReport    &trial,
                     const std::size_t    p,
                     const double         before,
                     const double         rate,
                     const double         touching)
    {
      const double tau   = trial.tau;
      double       theta = 2.;
      if (rate > 0.)
        // c_p(t) = c_p(t_n) + (t - t_n) (C udot^n)_p reaches 0;
        // N-CS++'s projection looks one step beyond the trial
        theta = -before / (rate * tau);
      else if (trial.active[p])
        {
          // pulled into contact (no approaching velocity): the
          // penetration the multiplier stands for, mu_p / S_ee
          const double end =
            trial.multipliers[p] /
            operators.step_matrix_diagonal(row.eliminated_dof());
          if (end > touching)
            theta = -before / (end - before);
        }
      return theta;
    }



    /// The fraction of the step of length @p tau at which the released row
    /// @p row (force @p force_before at t_n, constraint value @p after at
    /// the trial's end) loses its force.
    double
    release_fraction(const StepOperators &operators,
                     const ContactRow    &row,
                     const double         tau,
                     const double         force_before,
                     const double         after)
    {
      // released: the force from > 0 at t_n to the -2/tau^2 S_ee
      // gap_p that the trial's opened gap stands for
      const double end = 2. / (tau * tau) *
                         operators.step_matrix_diagonal(row.eliminated_dof()) *
                         after;
      return force_before / (force_before - end);
    }



    /// The least fraction of the trial step, not below its first hundredth,
    /// at which one of this rank's rows that @p comes_into_contact or
    /// @p is_released has its event (2 if none). Collective.
    template <typename ComesIntoContact, typename IsReleased>
    double
    earliest_event(const StepOperators       &operators,
                   const ContactRowOperator  &row_operator,
                   const std::vector<double> &forces_before,
                   const VectorType          &u_old,
                   const VectorType          &udot_old,
                   const VectorType          &u,
                   const StepReport          &trial,
                   const bool                 known,
                   const ComesIntoContact    &comes_into_contact,
                   const IsReleased          &is_released,
                   const MPI_Comm             comm)
    {
      // events in the first hundredth of the step are not located: the step
      // would be too short to be worth it (and it is where the step after a
      // located event finds its row, at a gap of round-off size)
      const double       smallest = 1e-2;
      const double       tau      = trial.tau;
      const ContactRows &rows     = row_operator.rows();
      const std::size_t  n        = row_operator.size();
      const auto         before   = row_operator.constraint_values(u_old);
      const auto         rate     = row_operator.apply(udot_old);
      const auto         after    = row_operator.constraint_values(u);
      // gaps below round-off of the problem's lengths (a row that a
      // located step left touching) locate nothing: their ratios would
      // be ratios of round-off, different on different numbers of ranks
      double length = 0.;
      for (std::size_t p = 0; known && p < n; ++p)
        length = std::max(
          {length, std::abs(rows.rows[p].gap), tau * std::abs(rate[p])});
      const double touching = 1e-9 * Utilities::MPI::max(length, comm);
      double       fraction = 2.;
      for (std::size_t p = 0; known && p < n; ++p)
        {
          double theta = 2.;
          if (comes_into_contact(p) && before[p] < -touching)
            theta = contact_fraction(
              operators, rows.rows[p], trial, p, before[p], rate[p], touching);
          else if (is_released(p) && after[p] < -touching)
            theta = release_fraction(
              operators, rows.rows[p], tau, forces_before[p], after[p]);
          if (theta >= smallest)
            fraction = std::min(fraction, theta);
        }
      return fraction;
    }
  } // namespace



  double
  StepSizeControl::event_fraction(const StepOperators       &operators,
                                  const ContactRowOperator  &row_operator,
                                  const std::vector<char>   &active_before,
                                  const std::vector<char>   &settled,
                                  const std::vector<double> &forces_before,
                                  const VectorType          &u_old,
                                  const VectorType          &udot_old,
                                  const VectorType          &u,
                                  const StepReport          &trial,
                                  const bool                 every_row,
                                  const MPI_Comm             comm)
  {
    const std::size_t n = row_operator.size();
    const bool known    = (active_before.size() == n && settled.size() == n);
    // the events located are the onset of contact (no row active at t_n)
    // and the separation (no row active in the trial): in a contact zone
    // that grows or shrinks node by node (a Hertz drop) locating each
    // node's event would shorten nearly every step, each with a new S
    bool any_before = false, any_after = false;
    for (std::size_t p = 0; known && p < n; ++p)
      {
        any_before = any_before || active_before[p];
        any_after  = any_after || trial.active[p];
      }
    const bool onset =
      every_row || !Utilities::MPI::logical_or(any_before, comm);
    const bool separation =
      every_row || !Utilities::MPI::logical_or(any_after, comm);
    // a row comes into contact if the trial's displacement step or its
    // projection holds it and it was free at t_n
    auto comes_into_contact = [&](const std::size_t p) {
      return onset && settled[p] && !active_before[p] &&
             (trial.active[p] || trial.projection_active[p]);
    };
    auto is_released = [&](const std::size_t p) {
      return separation && settled[p] && active_before[p] && !trial.active[p] &&
             forces_before.size() == n && forces_before[p] > 0.;
    };
    bool has_event = false;
    for (std::size_t p = 0; known && p < n && !has_event; ++p)
      has_event = comes_into_contact(p) || is_released(p);
    double fraction = 2.;
    if (Utilities::MPI::logical_or(has_event, comm))
      fraction = earliest_event(operators,
                                row_operator,
                                forces_before,
                                u_old,
                                udot_old,
                                u,
                                trial,
                                known,
                                comes_into_contact,
                                is_released,
                                comm);
    return Utilities::MPI::min(fraction, comm);
  }



  double
  StepSizeControl::estimate(const StepOperators &operators,
                            const VectorType    &udot_old,
                            const VectorType    &udot,
                            const double         tau)
  {
    velocity_norms[0] = operators.mass_norm(udot_old);
    velocity_norms[1] = operators.mass_norm(udot);
    if (!has_history)
      return 0.;
    const double scale =
      std::max({velocity_scale, velocity_norms[1], velocity_norms[0]});
    if (scale == 0.)
      return 0.;
    // a_n - a_{n-1}
    VectorType difference(udot);
    difference -= udot_old;
    difference /= tau;
    difference -= acceleration;
    return tau * operators.mass_norm(difference) /
           (6. * (1. + previous_tau / tau) * scale);
  }



  bool
  StepSizeControl::accept(const VectorType &udot_old,
                          const VectorType &udot,
                          const double      tau,
                          const double      eta,
                          const double      tolerance)
  {
    n_small = (has_history && eta < tolerance / 8.) ? n_small + 1 : 0;
    copy_with_layout(acceleration, udot);
    acceleration -= udot_old;
    acceleration /= tau;
    previous_tau = tau;
    velocity_scale =
      std::max({velocity_scale, velocity_norms[1], velocity_norms[0]});
    has_history = true;
    if (n_small >= 2)
      {
        n_small = 0;
        return true;
      }
    return false;
  }



  void
  StepSizeControl::save(std::map<std::string, std::string> &state) const
  {
    std::ostringstream s;
    s << std::setprecision(17) << previous_tau << " " << velocity_scale << " "
      << (has_history ? 1 : 0) << " " << n_small << " " << located_events << " "
      << repeated_steps;
    state["step_size_control"] = s.str();
  }



  void
  StepSizeControl::load(const std::map<std::string, std::string> &state,
                        const VectorType &checkpoint_acceleration)
  {
    reset();
    if (state.count("step_size_control") == 0)
      return;
    std::istringstream s(state.at("step_size_control"));
    int                history = 0;
    s >> previous_tau >> velocity_scale >> history >> n_small >>
      located_events >> repeated_steps;
    AssertThrow(!s.fail(),
                ExcMessage("the step size control's state in the checkpoint "
                           "is damaged"));
    has_history  = (history == 1);
    acceleration = checkpoint_acceleration;
  }
} // namespace dyncontact
