#include <deal.II/base/mpi.h>

#include <impm/base/errors.h>
#include <impm/coupling/couplings.h>

#include <algorithm>
#include <stdexcept>

// The scene's couplings together (Couplings): made from the registry by
// name, asked as one by the load step.
namespace impm
{
  template <int dim>
  void
  Couplings<dim>::declare_parameters(ParameterHandler &prm)
  {
    for (const auto &entry : CouplingList<dim>::entries())
      if (entry.declare_parameters)
        {
          prm.enter_subsection(entry.name);
          entry.declare_parameters(prm);
          prm.leave_subsection();
        }
  }



  template <int dim>
  Couplings<dim>::Couplings(const CouplingInputs<dim> &inputs)
  {
    for (const auto &entry : CouplingList<dim>::entries())
      {
        if (entry.declare_parameters)
          inputs.prm.enter_subsection(entry.name);
        std::unique_ptr<Coupling<dim>> coupling = entry.create(inputs);
        if (entry.declare_parameters)
          inputs.prm.leave_subsection();
        if (!coupling)
          continue;
        if (coupling->sets_point_volumes())
          {
            if (sets_volumes != nullptr)
              throw std::logic_error("Two couplings set the points' volumes.");
            sets_volumes = coupling.get();
          }
        couplings.push_back(std::move(coupling));
      }
    if (step_solver() != nullptr)
      {
        double surface_stiffness = 0.;
        for (const auto &coupling : couplings)
          {
            if (const std::string conflict = coupling->explicit_step_conflict();
                !conflict.empty())
              throw InputError(conflict);
            surface_stiffness =
              std::max(surface_stiffness, coupling->surface_stiffness());
          }
        for (const auto &coupling : couplings)
          coupling->use_explicit_steps(surface_stiffness);
      }
  }



  template <int dim>
  PointFields
  Couplings<dim>::point_fields() const
  {
    PointFields fields;
    for (const auto &coupling : couplings)
      for (const PointField &field : coupling->point_fields())
        fields.push_back(field);
    return fields;
  }



  template <int dim>
  bool
  Couplings<dim>::need_direct_solver() const
  {
    for (const auto &coupling : couplings)
      if (coupling->needs_direct_solver())
        return true;
    return false;
  }



  template <int dim>
  bool
  Couplings<dim>::set_up_system(const MaterialPoints<dim> &material_points,
                                LoadStepSystem<dim>       &system)
  {
    const std::vector<bool>   touched = system.touched_dofs();
    std::vector<unsigned int> n_rows;
    for (const auto &coupling : couplings)
      n_rows.push_back(coupling->prepare(material_points, system, touched));
    unsigned int n_coupling_rows = 0;
    for (const unsigned int n : n_rows)
      n_coupling_rows += n;
    // An explicit step has no matrix: no assembly groups either.
    system.number(touched, n_coupling_rows, step_solver() == nullptr);
    std::vector<std::vector<types::global_dof_index>> blocks;
    types::global_dof_index first = system.first_coupling_row();
    for (unsigned int c = 0; c < couplings.size(); ++c)
      {
        couplings[c]->setup(material_points,
                            system,
                            CouplingRows{first, system.owned_rows()},
                            blocks);
        first += n_rows[c];
      }
    // The global unknowns' count may change with the step (none so far
    // does): counted here, before the attempt.
    n_global = 0;
    for (const auto &coupling : couplings)
      n_global += coupling->n_global_unknowns();
    // An explicit step has no matrix.
    if (step_solver() != nullptr)
      return false;
    return system.make_pattern(blocks);
  }



  template <int dim>
  Coupling<dim> *
  Couplings<dim>::step_solver() const
  {
    for (const auto &coupling : couplings)
      if (coupling->solves_step())
        return coupling.get();
    return nullptr;
  }



  template <int dim>
  Tensor<1, dim>
  Couplings<dim>::force_from_material() const
  {
    Tensor<1, dim> force;
    for (const auto &coupling : couplings)
      force += coupling->force_from_material();
    return force;
  }



  template <int dim>
  bool
  Couplings<dim>::keep_energy_balance() const
  {
    return std::any_of(couplings.begin(),
                       couplings.end(),
                       [](const auto &coupling) {
                         return coupling->keeps_energy_balance();
                       });
  }



  template <int dim>
  std::string
  Couplings<dim>::run_failure() const
  {
    for (const auto &coupling : couplings)
      if (std::string failure = coupling->run_failure(); !failure.empty())
        return failure;
    return "";
  }



  template <int dim>
  void
  Couplings<dim>::account_step_energy(const LoadStepSystem<dim> &system,
                                      const NodalVector         &increment,
                                      const double work_of_loads) const
  {
    StepEnergy local;
    for (const auto &coupling : couplings)
      coupling->add_step_energy(system, increment, local);
    const MPI_Comm communicator = increment.get_mpi_communicator();
    StepEnergy     energy;
    energy.external_work =
      work_of_loads + Utilities::MPI::sum(local.external_work, communicator);
    energy.dissipated = Utilities::MPI::sum(local.dissipated, communicator);
    for (const auto &coupling : couplings)
      if (coupling->keeps_energy_balance())
        coupling->take_step_energy(energy);
  }



  template <int dim>
  bool
  Couplings<dim>::state_changed() const
  {
    bool changed = false;
    // Every coupling's check is collective: none is skipped.
    for (const auto &coupling : couplings)
      changed = coupling->state_changed() || changed;
    return changed;
  }



  template <int dim>
  Vector<double>
  Couplings<dim>::global_residuals() const
  {
    Vector<double> all(n_global);
    unsigned int   next = 0;
    for (const auto &coupling : couplings)
      if (coupling->n_global_unknowns() > 0)
        {
          const Vector<double> part = coupling->global_residuals();
          for (unsigned int j = 0; j < part.size(); ++j)
            all(next++) = part(j);
        }
    return all;
  }



  template <int dim>
  void
  Couplings<dim>::add_to_global_unknowns(const Vector<double> &correction) const
  {
    unsigned int next = 0;
    for (const auto &coupling : couplings)
      if (const unsigned int n = coupling->n_global_unknowns(); n > 0)
        {
          Vector<double> part(n);
          for (unsigned int j = 0; j < n; ++j)
            part(j) = correction(next++);
          coupling->add_to_global_unknowns(part);
        }
  }



  template <int dim>
  std::string
  Couplings<dim>::unbalanced_unknown(const unsigned int j) const
  {
    unsigned int first = 0;
    for (const auto &coupling : couplings)
      {
        const unsigned int n = coupling->n_global_unknowns();
        if (j < first + n)
          return coupling->unbalanced_unknown(j - first);
        first += n;
      }
    return "";
  }



  template class Couplings<2>;
  template class Couplings<3>;
} // namespace impm
