#include <deal.II/base/mpi.h>

#include <impm/base/errors.h>
#include <impm/coupling/coupling.h>

#include <stdexcept>

namespace impm
{
  template <int dim>
  std::vector<std::string>
  Coupling<dim>::notes(const Parameters::LinearSolverType) const
  {
    return {};
  }



  template <int dim>
  bool
  Coupling<dim>::needs_direct_solver() const
  {
    return false;
  }



  template <int dim>
  PointFields
  Coupling<dim>::point_fields() const
  {
    return {};
  }



  template <int dim>
  bool
  Coupling<dim>::holds_material(const unsigned int) const
  {
    return false;
  }



  template <int dim>
  void
  Coupling<dim>::check_start(const MaterialPoints<dim> &) const
  {}



  template <int dim>
  void
  Coupling<dim>::save(RunState &) const
  {}



  template <int dim>
  void
  Coupling<dim>::load(const RunState &)
  {}



  template <int dim>
  unsigned int
  Coupling<dim>::prepare(const MaterialPoints<dim> &,
                         const LoadStepSystem<dim> &,
                         const std::vector<bool> &)
  {
    return 0;
  }



  template <int dim>
  void
  Coupling<dim>::setup(const MaterialPoints<dim> &,
                       const LoadStepSystem<dim> &,
                       const CouplingRows &,
                       std::vector<std::vector<types::global_dof_index>> &)
  {}



  template <int dim>
  void
  Coupling<dim>::begin_attempt(const MaterialPoints<dim> &,
                               const LoadStepSystem<dim> &,
                               const StepSpan &)
  {}



  template <int dim>
  bool
  Coupling<dim>::needs_start_residual() const
  {
    return false;
  }



  template <int dim>
  void
  Coupling<dim>::set_start_residual(const NodalVector &)
  {}



  template <int dim>
  bool
  Coupling<dim>::solves_step() const
  {
    return false;
  }



  template <int dim>
  std::string
  Coupling<dim>::step_increment(const LoadStepSystem<dim> &, NodalVector &)
  {
    return "";
  }



  template <int dim>
  std::string
  Coupling<dim>::explicit_step_conflict() const
  {
    return "";
  }



  template <int dim>
  void
  Coupling<dim>::use_explicit_steps()
  {}



  template <int dim>
  bool
  Coupling<dim>::sets_point_volumes() const
  {
    return false;
  }



  template <int dim>
  bool
  Coupling<dim>::update_stresses(PointSteps<dim> &,
                                 const std::function<bool(unsigned int)> &)
  {
    throw std::logic_error("Coupling::update_stresses() of a coupling that "
                           "does not set the points' volumes.");
  }



  template <int dim>
  Tensor<4, dim>
  Coupling<dim>::point_tangent(const unsigned int,
                               const Tensor<4, dim> &tangent,
                               const Tensor<2, dim> &,
                               const Tensor<2, dim> &,
                               HoopTangent<dim> *,
                               const double,
                               const double)
  {
    return tangent;
  }



  template <int dim>
  void
  Coupling<dim>::add_forces(const LoadStepSystem<dim> &,
                            const NodalVector &,
                            NodalVector &)
  {}



  template <int dim>
  void
  Coupling<dim>::add_start_forces(const LoadStepSystem<dim> &system,
                                  const NodalVector         &increment,
                                  NodalVector               &internal_force)
  {
    add_forces(system, increment, internal_force);
  }



  template <int dim>
  void
  Coupling<dim>::add_row_residuals(
    std::vector<std::pair<types::global_dof_index, double>> &)
  {}



  template <int dim>
  double
  Coupling<dim>::reference_force() const
  {
    return 0.;
  }



  template <int dim>
  bool
  Coupling<dim>::state_changed() const
  {
    return false;
  }



  template <int dim>
  double
  Coupling<dim>::round_off_force() const
  {
    return 0.;
  }



  template <int dim>
  bool
  Coupling<dim>::add_constant_matrix(const LoadStepSystem<dim> &,
                                     TrilinosWrappers::SparseMatrix &)
  {
    return false;
  }



  template <int dim>
  bool
  Coupling<dim>::add_matrix(const PointGradients<dim> &,
                            const LoadStepSystem<dim> &,
                            TrilinosWrappers::SparseMatrix &)
  {
    return false;
  }



  template <int dim>
  void
  Coupling<dim>::add_solution(const TrilinosWrappers::MPI::Vector &)
  {}



  template <int dim>
  double
  Coupling<dim>::perturb_row(const types::global_dof_index, const double)
  {
    return 0.;
  }



  template <int dim>
  double
  Coupling<dim>::max_unknown_increment() const
  {
    return 0.;
  }



  template <int dim>
  StepRefusal
  Coupling<dim>::refuse_step(const MaterialPoints<dim> &,
                             const LoadStepSystem<dim> &,
                             const NodalVector &) const
  {
    return {};
  }



  template <int dim>
  unsigned int
  Coupling<dim>::n_global_unknowns() const
  {
    return 0;
  }



  template <int dim>
  Vector<double>
  Coupling<dim>::global_residuals() const
  {
    return Vector<double>();
  }



  template <int dim>
  void
  Coupling<dim>::global_coupling(const LoadStepSystem<dim> &,
                                 std::vector<NodalVector> &columns,
                                 std::vector<NodalVector> &rows,
                                 FullMatrix<double>       &corner) const
  {
    columns.clear();
    rows.clear();
    corner.reinit(0, 0);
  }



  template <int dim>
  void
  Coupling<dim>::add_to_global_unknowns(const Vector<double> &)
  {}



  template <int dim>
  std::string
  Coupling<dim>::unbalanced_unknown(const unsigned int) const
  {
    return "";
  }



  template <int dim>
  void
  Coupling<dim>::accept(MaterialPoints<dim> &,
                        const LoadStepSystem<dim> &,
                        const NodalVector &)
  {}



  template <int dim>
  void
  Coupling<dim>::initialize_points(MaterialPoints<dim> &)
  {}



  template <int dim>
  Tensor<1, dim>
  Coupling<dim>::force_from_material() const
  {
    return Tensor<1, dim>();
  }



  template <int dim>
  std::vector<std::string>
  Coupling<dim>::step_measure_columns() const
  {
    return {};
  }



  template <int dim>
  void
  Coupling<dim>::step_measures(const double, std::vector<StepMeasure> &) const
  {}



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
      for (const auto &coupling : couplings)
        {
          if (const std::string conflict = coupling->explicit_step_conflict();
              !conflict.empty())
            throw InputError(conflict);
          coupling->use_explicit_steps();
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



  template <int dim>
  void
  CouplingInputs<dim>::refuse_axisymmetry(const std::string &coupling) const
  {
    if (parameters.grid.axisymmetric)
      throw InputError(coupling + " is not yet available with "
                                  "Grid/Axisymmetric = true.");
  }



  template struct CouplingInputs<2>;
  template struct CouplingInputs<3>;
  template class Coupling<2>;
  template class Coupling<3>;
  template class Couplings<2>;
  template class Couplings<3>;
} // namespace impm
