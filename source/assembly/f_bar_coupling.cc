// F-bar as a coupling (Coupling's functions): the patches and their rows
// in the system, the stress update, the matrix, the pressure unknowns'
// residuals and corrections, and the registration. The patches' volumes,
// pressures and blocks are in f_bar.cc.
#include <impm/assembly/f_bar.h>
#include <impm/system/load_step_system.h>

#include <string>
#include <utility>
#include <vector>

namespace impm
{
  template <int dim>
  FBar<dim>::FBar(const CouplingInputs<dim> &inputs)
    : FBar(inputs.grid,
           inputs.parameters.material_points.cell_pressure_unknowns,
           inputs.parameters.material_points.pressure_jump_stabilisation)
  {}



  template <int dim>
  unsigned int
  FBar<dim>::prepare(const MaterialPoints<dim> &material_points,
                     const LoadStepSystem<dim> &,
                     const std::vector<bool> &)
  {
    return make_patches(material_points);
  }



  template <int dim>
  void
  FBar<dim>::setup(const MaterialPoints<dim> &material_points,
                   const LoadStepSystem<dim> &system,
                   const CouplingRows        &rows,
                   std::vector<std::vector<types::global_dof_index>> &blocks)
  {
    set_up_patches(
      material_points, system, grid.n_local_dofs(), rows.first, rows.owned);
    for (auto &patch : patch_rows())
      blocks.push_back(std::move(patch));
  }



  template <int dim>
  void
  FBar<dim>::begin_attempt(const MaterialPoints<dim> &,
                           const LoadStepSystem<dim> &,
                           const StepSpan &)
  {
    if (has_pressure_unknowns())
      reset_pressure_unknowns();
  }



  template <int dim>
  bool
  FBar<dim>::sets_point_volumes() const
  {
    return true;
  }



  template <int dim>
  bool
  FBar<dim>::update_stresses(
    PointSteps<dim>                         &point_steps,
    const std::function<bool(unsigned int)> &update_point)
  {
    if (has_pressure_unknowns())
      return equalise_pressures(point_steps, update_point);
    average(point_steps);
    bool admissible = true;
    for (unsigned int p = 0; p < point_steps.size(); ++p)
      admissible = update_point(p) && admissible;
    return admissible;
  }



  template <int dim>
  bool
  FBar<dim>::add_matrix(const PointGradients<dim>      &gradients,
                        const LoadStepSystem<dim>      &system,
                        TrilinosWrappers::SparseMatrix &matrix)
  {
    add_patch_stiffness(system.point_steps,
                        gradients,
                        matrix,
                        system.off_process_rows);
    return false;
  }



  template <int dim>
  void
  FBar<dim>::add_row_residuals(
    std::vector<std::pair<types::global_dof_index, double>> &rows)
  {
    if (!has_pressure_unknowns())
      return;
    const auto &own = pressure_residuals();
    rows.insert(rows.end(), own.begin(), own.end());
  }



  template <int dim>
  void
  FBar<dim>::add_solution(const TrilinosWrappers::MPI::Vector &solution)
  {
    if (has_pressure_unknowns())
      add_to_pressure_unknowns(solution);
  }



  template <int dim>
  double
  FBar<dim>::perturb_row(const types::global_dof_index row, const double amount)
  {
    return has_pressure_unknowns() ? perturb_pressure_unknown(row, amount) : 0.;
  }



  template <int dim>
  bool
  FBar<dim>::needs_direct_solver() const
  {
    return has_pressure_unknowns();
  }



  template <int dim>
  std::string
  FBar<dim>::explicit_step_conflict() const
  {
    if (!has_pressure_unknowns())
      return "";
    return "Material points/Cell pressure unknowns: the cell pressures are "
           "unknowns of the load step's system, which an explicit step does "
           "not solve; use plain F-bar ('Cell pressure unknowns = false') or "
           "an implicit integrator (Newmark or generalised-alpha).";
  }



  template <int dim>
  std::vector<std::string>
  FBar<dim>::notes(const Parameters::LinearSolverType linear_solver) const
  {
    if (!has_pressure_unknowns())
      return {};
    return {std::string("with cell pressure unknowns ") +
            (linear_solver == Parameters::LinearSolverType::gmres_amg ?
               "GMRES with AMG may not converge (its AMG does not solve "
               "the pressure rows); 'direct' or 'MUMPS' will" :
               "the linear solves are direct")};
  }



  template <int dim>
  std::vector<std::string>
  FBar<dim>::descriptions() const
  {
    return {description()};
  }



#define IMPM_INSTANTIATE(dim)                                                \
  template FBar<dim>::FBar(const CouplingInputs<dim> &);                     \
  template unsigned int FBar<dim>::prepare(const MaterialPoints<dim> &,      \
                                           const LoadStepSystem<dim> &,      \
                                           const std::vector<bool> &);       \
  template void         FBar<dim>::setup(                                    \
    const MaterialPoints<dim> &,                                     \
    const LoadStepSystem<dim> &,                                     \
    const CouplingRows &,                                            \
    std::vector<std::vector<types::global_dof_index>> &);            \
  template void FBar<dim>::begin_attempt(const MaterialPoints<dim> &,        \
                                         const LoadStepSystem<dim> &,        \
                                         const StepSpan &);                  \
  template bool FBar<dim>::sets_point_volumes() const;                       \
  template bool FBar<dim>::update_stresses(                                  \
    PointSteps<dim> &, const std::function<bool(unsigned int)> &);           \
  template bool FBar<dim>::add_matrix(const PointGradients<dim> &,           \
                                      const LoadStepSystem<dim> &,           \
                                      TrilinosWrappers::SparseMatrix &);     \
  template void FBar<dim>::add_row_residuals(                                \
    std::vector<std::pair<types::global_dof_index, double>> &);              \
  template void FBar<dim>::add_solution(                                     \
    const TrilinosWrappers::MPI::Vector &);                                  \
  template double      FBar<dim>::perturb_row(const types::global_dof_index, \
                                         const double);                 \
  template bool        FBar<dim>::needs_direct_solver() const;               \
  template std::string FBar<dim>::explicit_step_conflict() const;            \
  template std::vector<std::string> FBar<dim>::notes(                        \
    const Parameters::LinearSolverType) const;                               \
  template std::vector<std::string> FBar<dim>::descriptions() const;
  IMPM_INSTANTIATE(2)
  IMPM_INSTANTIATE(3)
#undef IMPM_INSTANTIATE


  IMPM_REGISTER_COUPLING(FBar,
                         "F-bar",
                         inputs.parameters.material_points.f_bar,
                         nullptr)
} // namespace impm
