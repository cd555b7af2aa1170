#include <deal.II/base/mpi.h>

#include <impm/solver/tangent_check.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace impm
{
  void
  TangentCheckResult::merge(const TangentCheckResult &other)
  {
    largest_row_difference =
      std::max(largest_row_difference, other.largest_row_difference);
    largest_matrix_difference =
      std::max(largest_matrix_difference, other.largest_matrix_difference);
    columns_across_kinks += other.columns_across_kinks;
  }



  namespace
  {
    /**
     * The largest entry and the largest difference of each row of a
     * check, and of the whole matrix.
     */
    struct RowDifferences
    {
      std::vector<double> entry, difference;
      double              largest_entry = 0., largest_difference = 0.;

      explicit RowDifferences(const unsigned int n_rows)
        : entry(n_rows, 0.)
        , difference(n_rows, 0.)
      {}

      void
      compare(const unsigned int row, const double value, const double fd)
      {
        const double gap   = std::abs(value - fd);
        entry[row]         = std::max(entry[row], std::abs(value));
        difference[row]    = std::max(difference[row], gap);
        largest_entry      = std::max(largest_entry, std::abs(value));
        largest_difference = std::max(largest_difference, gap);
      }
    };
  } // namespace



  template <int dim>
  TangentCheck<dim>::TangentCheck(const BackgroundGrid<dim> &grid,
                                  const LoadStepSystem<dim> &system,
                                  Couplings<dim>            &couplings)
    : grid(grid)
    , system(system)
    , couplings(couplings)
  {}



  namespace
  {
    /**
     * One tangent check's view of the iterate: the rows it compares, the
     * forces at the iterate, and the differences found.
     */
    template <int dim>
    struct Comparison
    {
      /** This process's nodal rows: (system index, local DoF). */
      std::vector<std::pair<types::global_dof_index, unsigned int>> rows;
      /** The couplings' rows this process owns (found at the first
       *  evaluation). */
      std::vector<types::global_dof_index> coupling_rows;
      bool                                 coupling_rows_known = false;
      /** The forces at the plus and minus perturbations. */
      std::vector<double> plus, minus;
      /** The differences of the local rows and of the global unknowns'
       *  rows. */
      RowDifferences local{0}, global{0};
      /** The columns left out. */
      unsigned int columns_across_kinks = 0;

      /**
       * The forces at the current iterate into @p values: the nodal rows',
       * the couplings' rows' (their residuals), and the global unknowns'
       * (the residual's change with the sign turned: the applied force is
       * fixed).
       */
      void
      evaluate(std::vector<double>         &values,
               const NodalVector           &internal_force,
               const std::function<bool()> &update_forces,
               const Couplings<dim>        &couplings)
      {
        if (!update_forces())
          throw std::runtime_error("Testing/Check tangent: a perturbed "
                                   "iterate is inadmissible.");
        values.resize(rows.size());
        for (unsigned int r = 0; r < rows.size(); ++r)
          values[r] = internal_force.local_element(rows[r].second);
        std::vector<std::pair<types::global_dof_index, double>> residuals;
        for (const auto &coupling : couplings.list())
          coupling->add_row_residuals(residuals);
        for (const auto &[row, residual] : residuals)
          {
            if (!coupling_rows_known)
              coupling_rows.push_back(row);
            values.push_back(residual);
          }
        coupling_rows_known           = true;
        const Vector<double> residual = couplings.global_residuals();
        for (unsigned int j = 0; j < residual.size(); ++j)
          values.push_back(-residual[j]);
      }
    };
  } // namespace



  template <int dim>
  TangentCheckResult
  TangentCheck<dim>::run(NodalVector                 &increment,
                         const NodalVector           &internal_force,
                         const std::function<bool()> &update_forces,
                         const BorderedBlock         &border) const
  {
    Comparison<dim> comparison;
    for (unsigned int i = 0; i < grid.n_locally_owned_dofs(); ++i)
      if (system.system_index(i) != numbers::invalid_dof_index)
        comparison.rows.emplace_back(system.system_index(i), i);
    const auto evaluate = [&](std::vector<double> &values) {
      comparison.evaluate(values, internal_force, update_forces, couplings);
    };
    evaluate(comparison.plus);
    comparison.local =
      RowDifferences(comparison.rows.size() + comparison.coupling_rows.size());
    comparison.global = RowDifferences(couplings.n_global_unknowns());

    // A perturbation small against the cells, large against round-off.
    double cell = std::numeric_limits<double>::max();
    for (unsigned int d = 0; d < dim; ++d)
      cell = std::min(cell, grid.cartesian().cell_size[d]);
    const double perturbation = 1e-7 * cell;

    for (types::global_dof_index column = 0; column < system.n_dofs(); ++column)
      check_system_column(
        column, perturbation, increment, border, evaluate, comparison);
    for (unsigned int j = 0; j < couplings.n_global_unknowns(); ++j)
      check_global_column(j, perturbation, border, evaluate, comparison);
    // Back to the iterate's stresses and forces.
    evaluate(comparison.plus);
    return conclude(comparison);
  }



  template <int dim>
  template <typename Comparison, typename Evaluate>
  void
  TangentCheck<dim>::check_system_column(const types::global_dof_index column,
                                         const double         perturbation,
                                         NodalVector         &increment,
                                         const BorderedBlock &border,
                                         const Evaluate      &evaluate,
                                         Comparison          &comparison) const
  {
    const MPI_Comm communicator = grid.get_triangulation().get_communicator();
    const auto    &rows         = comparison.rows;
    const unsigned int n_rows =
      comparison.rows.size() + comparison.coupling_rows.size();
    // The owner perturbs the DoF; the ghosts follow.
    unsigned int local_dof = numbers::invalid_unsigned_int;
    for (const auto &[index, i] : rows)
      if (index == column)
        local_dof = i;
    // A coupling's row is perturbed by its owner, with the scale it says
    // (a pressure over E: by the perturbation over the cell size), which
    // all processes learn.
    double     scale   = 0.;
    const auto perturb = [&](const double amount) {
      increment.zero_out_ghost_values();
      if (local_dof != numbers::invalid_unsigned_int)
        increment.local_element(local_dof) += amount;
      increment.update_ghost_values();
      scale = 0.;
      for (const auto &coupling : couplings.list())
        scale = std::max(scale, coupling->perturb_row(column, amount));
    };
    perturb(perturbation);
    const bool owns_column =
      local_dof != numbers::invalid_unsigned_int || scale > 0.;
    const double column_scale = Utilities::MPI::max(scale, communicator);
    evaluate(comparison.plus);
    // A coupling whose state differs between the iterate and a perturbed
    // one has a kink there: its differences are no derivative.
    bool across_kink = couplings.state_changed();
    perturb(-2. * perturbation);
    evaluate(comparison.minus);
    across_kink = couplings.state_changed() || across_kink;
    perturb(perturbation);
    if (across_kink)
      {
        ++comparison.columns_across_kinks;
        return;
      }
    const auto  &plus = comparison.plus, &minus = comparison.minus;
    const double step =
      2. * perturbation * (column_scale > 0. ? column_scale : 1.);
    for (unsigned int r = 0; r < rows.size(); ++r)
      comparison.local.compare(r,
                               system.matrix.el(rows[r].first, column),
                               (plus[r] - minus[r]) / step);
    for (unsigned int r = rows.size(); r < n_rows; ++r)
      comparison.local.compare(
        r,
        system.matrix.el(comparison.coupling_rows[r - rows.size()], column),
        (plus[r] - minus[r]) / step);
    // The global unknowns' rows, on the column's owner.
    if (owns_column)
      for (unsigned int j = 0; j < couplings.n_global_unknowns(); ++j)
        comparison.global.compare(j,
                                  border.rows[j](column),
                                  (plus[n_rows + j] - minus[n_rows + j]) /
                                    step);
  }



  template <int dim>
  template <typename Comparison, typename Evaluate>
  void
  TangentCheck<dim>::check_global_column(const unsigned int   j,
                                         const double         perturbation,
                                         const BorderedBlock &border,
                                         const Evaluate      &evaluate,
                                         Comparison          &comparison) const
  {
    const unsigned int n_global = couplings.n_global_unknowns();
    const unsigned int n_rows =
      comparison.rows.size() + comparison.coupling_rows.size();
    // The unknown moves, the DoFs stay.
    Vector<double> move(n_global);
    const auto     shift = [&](const double amount) {
      move    = 0.;
      move(j) = amount;
      couplings.add_to_global_unknowns(move);
    };
    shift(perturbation);
    evaluate(comparison.plus);
    bool across_kink = couplings.state_changed();
    shift(-2. * perturbation);
    evaluate(comparison.minus);
    across_kink = couplings.state_changed() || across_kink;
    shift(perturbation);
    if (across_kink)
      {
        ++comparison.columns_across_kinks;
        return;
      }
    const auto &plus = comparison.plus, &minus = comparison.minus;
    for (unsigned int r = 0; r < comparison.rows.size(); ++r)
      comparison.local.compare(r,
                               border.columns[j](comparison.rows[r].first),
                               (plus[r] - minus[r]) / (2. * perturbation));
    for (unsigned int i = 0; i < n_global; ++i)
      comparison.global.compare(i,
                                border.corner(i, j),
                                (plus[n_rows + i] - minus[n_rows + i]) /
                                  (2. * perturbation));
  }



  template <int dim>
  template <typename Comparison>
  TangentCheckResult
  TangentCheck<dim>::conclude(Comparison &comparison) const
  {
    const MPI_Comm  communicator = grid.get_triangulation().get_communicator();
    RowDifferences &local = comparison.local, &global = comparison.global;
    // The global rows are spread over the processes.
    Utilities::MPI::max(global.entry, communicator, global.entry);
    Utilities::MPI::max(global.difference, communicator, global.difference);
    const double largest_entry =
      Utilities::MPI::max(std::max(local.largest_entry, global.largest_entry),
                          communicator);
    const double largest_difference =
      Utilities::MPI::max(std::max(local.largest_difference,
                                   global.largest_difference),
                          communicator);
    // A row without entries is measured against round-off of the matrix's
    // largest.
    const double floor      = 1e-12 * largest_entry;
    double       row_result = 0.;
    for (const RowDifferences *part : {&local, &global})
      for (unsigned int r = 0; r < part->entry.size(); ++r)
        if (part->difference[r] > 0.)
          row_result =
            std::max(row_result,
                     part->difference[r] / std::max(part->entry[r], floor));
    // Every process counts the same columns across kinks (a coupling's
    // state change is agreed by all).
    TangentCheckResult result;
    result.columns_across_kinks = comparison.columns_across_kinks;
    result.largest_row_difference =
      Utilities::MPI::max(row_result, communicator);
    result.largest_matrix_difference =
      largest_entry > 0. ? largest_difference / largest_entry : 0.;
    return result;
  }



  template class TangentCheck<2>;
  template class TangentCheck<3>;
} // namespace impm
