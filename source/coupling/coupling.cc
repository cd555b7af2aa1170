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
  Coupling<dim>::step_increment(const LoadStepSystem<dim> &,
                                NodalVector &,
                                double &)
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
  double
  Coupling<dim>::surface_stiffness() const
  {
    return 0.;
  }



  template <int dim>
  void
  Coupling<dim>::use_explicit_steps(const double)
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
  void
  Coupling<dim>::add_step_energy(const LoadStepSystem<dim> &,
                                 const NodalVector &,
                                 StepEnergy &)
  {}



  template <int dim>
  bool
  Coupling<dim>::keeps_energy_balance() const
  {
    return false;
  }



  template <int dim>
  std::string
  Coupling<dim>::run_failure() const
  {
    return "";
  }



  template <int dim>
  void
  Coupling<dim>::take_step_energy(const StepEnergy &)
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
} // namespace impm
