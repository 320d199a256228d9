// Energies (Theorem 3.2): E_kin = 1/2 udot^T M udot, E_el = 1/2 u^T A u -
// f^T u, and the viscous dissipation W_visc += (du)^T B (du) / tau,
// accumulated over the steps, and with Time integration/Numerical
// dissipation theta > 0 the scheme's own dissipation W_num += theta (du)^T A
// (du); with loads that change in time (f(t)) the work of their change
// W_load -= 1/2 (f^{n+1} - f^n)^T (u^n + u^{n+1}) (column work_load_change),
// and with Dirichlet data that move the work of their force R on the body
// W_D += R^T (u^{n+1} - u^n) (column work_prescribed), and with rigid
// obstacles that move the work of their contact forces W_obs (column
// work_obstacles, StepReport::obstacle_work);
// E_kin + E_el + W_visc (+ W_num) (- W_load - W_D - W_obs) is constant
// without contact and non-increasing with contact.
//
// The balance monitor: energy_balance = E + W_visc (+ W_num) - E(0) minus the
// energy
// changes of mesh transfers, which Theorem 3.2 keeps <= 0 (the step's
// residual does no work on its increment: ActiveSetSolver's line search).
// A step that raises it by more than 1e-2 * Step solver tolerance (but
// within [1e-9, 1e-4]) times the run's energy scale
// gets a warning with the step, the size and the remedy.

#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/mesh_refinement/mesh_transfer.h>
#include <dyncontact/postprocess/interface.h>
#include <dyncontact/time_stepping/integrators.h>
#include <dyncontact/time_stepping/simulation_control.h>
#include <dyncontact/time_stepping/time_integration_parameters.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace dyncontact
{
  namespace Postprocess
  {
    template <int dim>
    class Energy : public Interface<dim>
    {
    public:
      /// E + W_visc (+ W_num) at the start and the end, the largest increase
      /// between steps and whether Theorem 3.2 held within the monitor's
      /// tolerance.
      std::string
      summary(const Statistics &s, const SummaryInput &input) const override
      {
        if (input.is_static)
          return "";
        const auto time        = s.column("time");
        const auto kinetic     = s.column("energy_kinetic");
        const auto elastic     = s.column("energy_elastic");
        auto       dissipation = s.column("dissipation_viscous");
        const bool numerical   = s.has_column("dissipation_numerical");
        if (numerical)
          {
            const auto w_num = s.column("dissipation_numerical");
            for (unsigned int r = 0; r < dissipation.size(); ++r)
              dissipation[r] += w_num[r];
          }
        // the energy the loads' change in time supplied counts as a source
        const bool load_change = s.has_column("work_load_change");
        const bool moving      = s.has_column("work_prescribed");
        const bool obstacles   = s.has_column("work_obstacles");
        for (const std::string column :
             {"work_load_change", "work_prescribed", "work_obstacles"})
          if (s.has_column(column))
            {
              const auto w = s.column(column);
              for (unsigned int r = 0; r < dissipation.size(); ++r)
                dissipation[r] -= w[r];
            }
        const auto         balance = s.column("energy_balance");
        const std::string  energy  = input.dim == 2 ? "J/m" : "J";
        const unsigned int last    = s.rows.size() - 1;
        double             scale = 0., increase = 0.;
        unsigned           at = 0;
        for (unsigned int r = 0; r <= last; ++r)
          {
            scale = std::max(scale,
                             kinetic[r] + std::abs(elastic[r]) +
                               std::abs(dissipation[r]));
            if (r > 0 && balance[r] - balance[r - 1] > increase)
              {
                increase = balance[r] - balance[r - 1];
                at       = r;
              }
          }
        const double       relative = increase / std::max(scale, 1e-300);
        std::ostringstream out;
        out << std::setprecision(6) << "energy E + W_visc"
            << (numerical ? " + W_num" : "") << (load_change ? " - W_load" : "")
            << (moving ? " - W_D" : "") << (obstacles ? " - W_obs" : "") << ": "
            << kinetic[0] + elastic[0] + dissipation[0] << " " << energy
            << " at the start, "
            << kinetic[last] + elastic[last] + dissipation[last] << " "
            << energy << " at the end, energy_balance " << balance[last] << " "
            << energy << "\n"
            << "largest energy increase between steps: " << increase << " "
            << energy;
        if (increase > 0.)
          out << " at t = " << time[at] << " s";
        out << " (" << relative << " of the energy scale " << scale << " "
            << energy << "); Theorem 3.2 "
            << (relative <= input.energy_tolerance ? "held" : "did not hold")
            << " within the monitor's tolerance " << input.energy_tolerance
            << "\n";
        return out.str();
      }


      std::vector<std::string>
      columns() const override
      {
        std::vector<std::string> names = {"energy_kinetic",
                                          "energy_elastic",
                                          "dissipation_viscous",
                                          "energy_total",
                                          "energy_balance"};
        if (theta() > 0.)
          names.insert(names.begin() + 3, "dissipation_numerical");
        if (loads_change())
          names.insert(names.end() - 2, "work_load_change");
        if (moves())
          names.insert(names.end() - 2, "work_prescribed");
        if (obstacles_move())
          names.insert(names.end() - 2, "work_obstacles");
        return names;
      }

      void
      execute(std::vector<double> &row) override
      {
        const SemiDiscreteSystem<dim> &system = this->get_system();
        const VectorType              &u      = this->get_solution();
        VectorType                     M_udot(u);
        const auto [kinetic, elastic] =
          system.energies(u, this->get_velocity(), M_udot);
        // (the static problem has no time: no viscous work, no balance)
        const bool is_static = this->get_integrator().get_scheme().is_static;
        if (this->get_control().get_step() > 0 && system.is_viscous() &&
            !is_static)
          {
            VectorType du(u), B_du(u);
            du -= this->get_old_solution();
            system.viscous_vmult(B_du, du);
            dissipation += (B_du * du) / this->get_step_report().tau;
          }
        if (this->get_control().get_step() > 0)
          numerical += this->get_step_report().numerical_dissipation;
        if (this->get_control().get_step() > 0 && loads_change() && !is_static)
          {
            // the work of the loads' change: with E_el = 1/2 u^T A u -
            // f(t)^T u, a step changes E by -1/2 (f^{n+1} - f^n)^T (u^n +
            // u^{n+1}) beyond the dissipation (doc/algorithms.md)
            VectorType df(system.get_load()), sum(u);
            df -= system.get_previous_load();
            sum += this->get_old_solution();
            load_work -= 0.5 * (df * sum);
          }
        if (this->get_control().get_step() > 0 && moves() && !is_static)
          {
            // the work of the Dirichlet data that move: their force on the
            // body times the step's displacement there
            VectorType du(u);
            du -= this->get_old_solution();
            prescribed_work +=
              this->get_integrator().get_operators().prescribed_reaction() * du;
          }
        if (this->get_control().get_step() > 0 && obstacles_move() &&
            !is_static)
          obstacle_work += this->get_step_report().obstacle_work;
        const double total = kinetic + elastic + dissipation + numerical -
                             load_work - prescribed_work - obstacle_work;
        const unsigned int step = this->get_control().get_step();
        if (step == 0)
          initial = total;
        else
          transfers += this->get_mesh_transfer().energy_change;
        const double balance   = is_static ? 0. : total - initial - transfers;
        scale                  = std::max(scale,
                         kinetic + std::abs(elastic) + dissipation + numerical +
                           std::abs(load_work) + std::abs(prescribed_work) +
                           std::abs(obstacle_work));
        const double tolerance = this->get_integrator()
                                   .get_operators()
                                   .get_solver_parameters()
                                   .energy_tolerance();
        if (step > 0 && !is_static &&
            balance - previous_balance > tolerance * scale)
          {
            ++n_increases;
            if (n_increases <= 3)
              this->get_pcout()
                << std::setprecision(3) << "   warning: step " << step
                << " (t = " << this->get_control().get_time()
                << " s): E + W_visc" << (theta() > 0. ? " + W_num" : "")
                << (loads_change() ? " - W_load" : "")
                << (moves() ? " - W_D" : "")
                << (obstacles_move() ? " - W_obs" : "") << " grew by "
                << balance - previous_balance << " J ("
                << 100. * (balance - previous_balance) / scale
                << "% of the energy), which Theorem 3.2 excludes. The "
                   "linear solver stops too early for this problem (the "
                   "work of contact forces on moving obstacles and of "
                   "prescribed displacements, and the L2 projection of two "
                   "bodies, are only as accurate as it): lower "
                   "'Contact solver/Step solver tolerance'."
                << (curved_obstacle_moves() ?
                      " Or: a curved rigid obstacle moves, whose constraint "
                      "is linearised at each node's reference position; "
                      "its normal turns along the path, and the balance "
                      "holds only up to that linearisation "
                      "(doc/algorithms.md, \"Rigid obstacles that move\")." :
                      "")
                << (n_increases == 3 ? " (Further such warnings are not "
                                       "printed; see the column "
                                       "energy_balance.)" :
                                       "")
                << std::endl;
          }
        previous_balance = balance;
        row.insert(row.end(), {kinetic, elastic, dissipation});
        if (theta() > 0.)
          row.push_back(numerical);
        if (loads_change())
          row.push_back(load_work);
        if (moves())
          row.push_back(prescribed_work);
        if (obstacles_move())
          row.push_back(obstacle_work);
        row.insert(row.end(), {kinetic + elastic, balance});
      }

      void
      save(std::map<std::string, std::string> &state) const override
      {
        std::ostringstream s;
        s << std::setprecision(17) << dissipation << " " << initial << " "
          << transfers << " " << scale << " " << previous_balance << " "
          << n_increases;
        state["viscous_dissipation"] = s.str();
        if (theta() > 0.)
          {
            std::ostringstream w;
            w << std::setprecision(17) << numerical;
            state["numerical_dissipation"] = w.str();
          }
        if (loads_change())
          {
            std::ostringstream w;
            w << std::setprecision(17) << load_work;
            state["load_change_work"] = w.str();
          }
        if (moves())
          {
            std::ostringstream w;
            w << std::setprecision(17) << prescribed_work;
            state["prescribed_work"] = w.str();
          }
        if (obstacles_move())
          {
            std::ostringstream w;
            w << std::setprecision(17) << obstacle_work;
            state["obstacle_work"] = w.str();
          }
      }

      void
      load(const std::map<std::string, std::string> &state) override
      {
        std::istringstream s(state.at("viscous_dissipation"));
        // token by token: std::stod reads nan and inf, operator>> does not
        std::string token;
        for (double *value :
             {&dissipation, &initial, &transfers, &scale, &previous_balance})
          {
            s >> token;
            AssertThrow(!s.fail(),
                        ExcMessage("the energies in the checkpoint are "
                                   "damaged"));
            *value = std::stod(token);
          }
        s >> n_increases;
        // (a checkpoint of theta = 0 has none; theta is one of the
        // parameters a resumed run must keep)
        if (state.count("numerical_dissipation"))
          numerical = std::stod(state.at("numerical_dissipation"));
        if (state.count("load_change_work"))
          load_work = std::stod(state.at("load_change_work"));
        if (state.count("prescribed_work"))
          prescribed_work = std::stod(state.at("prescribed_work"));
        if (state.count("obstacle_work"))
          obstacle_work = std::stod(state.at("obstacle_work"));
      }

    private:
      /// Time integration/Numerical dissipation.
      double
      theta() const
      {
        return this->get_time_integration().numerical_dissipation;
      }

      /// Whether the scene's loads change in time (FunctionLoads).
      bool
      loads_change() const
      {
        return this->get_scene().function_loads().time_dependent;
      }

      double dissipation = 0.;
      double numerical   = 0.;
      /// Whether Dirichlet data move (Scene::prescribed_displacements()).
      bool
      moves() const
      {
        return !this->get_scene().prescribed_displacements().empty();
      }

      /// Whether a rigid obstacle moves (RigidObstacle::motion).
      bool
      obstacles_move() const
      {
        for (const auto &obstacle : this->get_scene().obstacles())
          if (obstacle.motion != nullptr)
            return true;
        return false;
      }

      /// Whether a rigid obstacle that is no half-space moves.
      bool
      curved_obstacle_moves() const
      {
        for (const auto &obstacle : this->get_scene().obstacles())
          if (obstacle.motion != nullptr &&
              obstacle.shape != RigidObstacle<dim>::Shape::half_space)
            return true;
        return false;
      }

      /// the work of the loads' change in time, W_load, of the Dirichlet
      /// data that move, W_D, and of the rigid obstacles that move, W_obs
      double       load_work        = 0.;
      double       prescribed_work  = 0.;
      double       obstacle_work    = 0.;
      double       initial          = 0.;
      double       transfers        = 0.;
      double       scale            = 0.;
      double       previous_balance = 0.;
      unsigned int n_increases      = 0;
    };

    DYNCONTACT_REGISTER_POSTPROCESSOR(Energy,
                                      "energy",
                                      "kinetic and elastic energy, viscous "
                                      "dissipation (Theorem 3.2)")



    /**
     * The energies of each body where a scene has more than one: E_kin,b =
     * 1/2 udot_b^T M udot_b and E_el,b = 1/2 u_b^T A u_b - f_b^T u_b (M and
     * A couple no bodies, so these sum to the totals of "energy").
     */
    template <int dim>
    class BodyEnergy : public Interface<dim>
    {
    public:
      bool
      applies() const override
      {
        return this->get_scene().n_bodies() > 1;
      }

      std::vector<std::string>
      columns() const override
      {
        std::vector<std::string> names;
        for (const std::string energy : {"kinetic", "elastic"})
          for (unsigned int b = 1; b <= this->get_scene().n_bodies(); ++b)
            names.push_back("energy_" + energy + "_body" + std::to_string(b));
        return names;
      }

      void
      execute(std::vector<double> &row) override
      {
        const SemiDiscreteSystem<dim> &system   = this->get_system();
        const unsigned int             n_bodies = this->get_scene().n_bodies();
        const VectorType              &u        = this->get_solution();
        const VectorType              &udot     = this->get_velocity();
        const SystemMatrices           matrices = system.matrices();
        VectorType                     M_udot;
        matrices.mass_vmult(M_udot, udot);
        // (A u is cached from the total energy)
        const VectorType                 &A_u = matrices.stiffness_vmult(u);
        const VectorType                 &f   = system.get_load();
        std::vector<double>               sums(2 * n_bodies, 0.);
        const std::vector<unsigned char> &slots = system.get_owned_dof_slots();
        const double *M_v = M_udot.begin(), *v = udot.begin(),
                     *A_x = A_u.begin(), *f_x = f.begin(), *x = u.begin();
        for (std::size_t k = 0; k < slots.size(); ++k)
          {
            const unsigned int body = slots[k] / dim;
            sums[body] += 0.5 * M_v[k] * v[k];
            sums[n_bodies + body] += (0.5 * A_x[k] - f_x[k]) * x[k];
          }
        Utilities::MPI::sum(sums, this->get_mpi_communicator(), sums);
        row.insert(row.end(), sums.begin(), sums.end());
      }
    };

    DYNCONTACT_REGISTER_POSTPROCESSOR(BodyEnergy,
                                      "body energy",
                                      "kinetic and elastic energy of each "
                                      "body")
  } // namespace Postprocess
} // namespace dyncontact
