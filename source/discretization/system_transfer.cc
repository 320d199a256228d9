#include <deal.II/distributed/solution_transfer.h>

#include <dyncontact/base/triangulation.h>
#include <dyncontact/discretization/semi_discrete_system.h>
#include <dyncontact/discretization/serial_mesh_file.h>
#include <dyncontact/discretization/serial_transfer.h>

// SemiDiscreteSystem: the transfer of the state to an adapted mesh, and the
// mesh and the vectors of a checkpoint.

namespace dyncontact
{
  template <int dim>
  bool
  SemiDiscreteSystem<dim>::is_serial() const
  {
    return as_distributed(dof_handler.get_triangulation()) == nullptr;
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::prepare_for_refinement(const VectorType &u,
                                                  const VectorType &udot)
  {
    if (is_serial())
      {
        serial_transfer = std::make_unique<SerialTransfer<dim>>();
        serial_transfer->prepare(dof_handler, {&u, &udot});
      }
    else
      {
        // (p4est's transfer reads the ghosted copies when the mesh
        // changes)
        transferred = {ghosted(u), ghosted(udot)};
        transfer    = std::make_unique<
          parallel::distributed::SolutionTransfer<dim, VectorType>>(
          dof_handler);
        transfer->prepare_for_coarsening_and_refinement(
          {&transferred[0], &transferred[1]});
      }
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::interpolate_after_refinement(VectorType &u,
                                                        VectorType &udot)
  {
    reinit_vector(u);
    reinit_vector(udot);
    if (serial_transfer)
      {
        serial_transfer->interpolate(dof_handler, {&u, &udot});
        serial_transfer.reset();
      }
    else
      {
        std::vector<VectorType *> out = {&u, &udot};
        transfer->interpolate(out);
        transfer.reset();
      }
    transferred.clear();
    constraints.distribute(u);
    constraints.distribute(udot);
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::save(const std::string                     &file,
                                const std::vector<const VectorType *> &vectors)
  {
    if (is_serial())
      {
        write_state_file(file, dof_handler, vectors);
        return;
      }
    // (p4est's transfer packs the values of ghosted vectors)
    std::vector<VectorType>         copies;
    std::vector<const VectorType *> pointers;
    for (const VectorType *v : vectors)
      copies.push_back(ghosted(*v));
    for (const VectorType &v : copies)
      pointers.push_back(&v);
    write_state_file(file, dof_handler, pointers);
  }



  template <int dim>
  void
  write_state_file(const std::string                     &file,
                   const DoFHandler<dim>                 &dof_handler,
                   const std::vector<const VectorType *> &ghosted)
  {
    if (const auto *distributed =
          as_distributed(dof_handler.get_triangulation()))
      {
        parallel::distributed::SolutionTransfer<dim, VectorType> transfer(
          dof_handler);
        if (!ghosted.empty())
          transfer.prepare_for_serialization(ghosted);
        distributed->save(file);
      }
    else
      SerialMeshFile::write(file, dof_handler, ghosted);
  }



  template <int dim>
  void
  read_state_vectors(const std::string               &file,
                     const DoFHandler<dim>           &dof_handler,
                     const std::vector<VectorType *> &vectors)
  {
    if (as_distributed(dof_handler.get_triangulation()) == nullptr)
      SerialMeshFile::read_vectors(file, dof_handler, vectors);
    else
      {
        parallel::distributed::SolutionTransfer<dim, VectorType> loader(
          dof_handler);
        std::vector<VectorType *> out = vectors;
        loader.deserialize(out);
      }
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::load_mesh(const std::string  &file,
                                     Triangulation<dim> &triangulation)
  {
    if (auto *distributed = as_distributed(triangulation))
      distributed->load(file);
    else
      SerialMeshFile::read_refinement(file, triangulation);
  }



  template <int dim>
  void
  SemiDiscreteSystem<dim>::load_vectors(
    const std::string               &file,
    const std::vector<VectorType *> &vectors)
  {
    for (VectorType *v : vectors)
      reinit_vector(*v);
    read_state_vectors(file, dof_handler, vectors);
  }



  // (the class is instantiated in semi_discrete_system.cc)
#define DYNCONTACT_INSTANTIATE(dim)                                        \
  template bool SemiDiscreteSystem<dim>::is_serial() const;                \
  template void SemiDiscreteSystem<dim>::prepare_for_refinement(           \
    const VectorType &, const VectorType &);                               \
  template void SemiDiscreteSystem<dim>::interpolate_after_refinement(     \
    VectorType &, VectorType &);                                           \
  template void SemiDiscreteSystem<dim>::save(                             \
    const std::string &, const std::vector<const VectorType *> &);         \
  template void SemiDiscreteSystem<dim>::load_mesh(const std::string &,    \
                                                   Triangulation<dim> &);  \
  template void SemiDiscreteSystem<dim>::load_vectors(                     \
    const std::string &, const std::vector<VectorType *> &);               \
  template void write_state_file(const std::string &,                      \
                                 const DoFHandler<dim> &,                  \
                                 const std::vector<const VectorType *> &); \
  template void read_state_vectors(const std::string &,                    \
                                   const DoFHandler<dim> &,                \
                                   const std::vector<VectorType *> &);
  DYNCONTACT_INSTANTIATE(2)
  DYNCONTACT_INSTANTIATE(3)
#undef DYNCONTACT_INSTANTIATE
} // namespace dyncontact
