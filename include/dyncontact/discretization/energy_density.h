#ifndef dyncontact_discretization_energy_density_h
#define dyncontact_discretization_energy_density_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <dyncontact/scenes/material.h>

namespace dyncontact
{
  /// The energy density 1/2 rho |v|^2 + 1/2 sigma(e) : eps(e) of a velocity
  /// @p v and a displacement gradient @p grad (J/m^3): the integrand of the
  /// physical energy norm (exact errors, reference states, coarsening).
  template <int dim>
  inline double
  energy_density(const Material               &material,
                 const dealii::Tensor<1, dim> &v,
                 const dealii::Tensor<2, dim> &grad)
  {
    const dealii::SymmetricTensor<2, dim> eps = dealii::symmetrize(grad);
    return 0.5 * material.density * (v * v) +
           0.5 * (2. * material.mu() * (eps * eps) +
                  material.lambda() * dealii::trace(eps) * dealii::trace(eps));
  }
} // namespace dyncontact

#endif
