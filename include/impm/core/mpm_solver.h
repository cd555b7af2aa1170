#ifndef impm_core_mpm_solver_h
#define impm_core_mpm_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/timer.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <deal.II/particles/particle_handler.h>

#include <impm/basis/basis_functions.h>
#include <impm/core/effects.h>
#include <impm/core/parameters.h>
#include <impm/core/point_properties.h>
#include <impm/io/point_output.h>
#include <impm/mechanics/material.h>

#include <fstream>
#include <limits>
#include <memory>
#include <unordered_map>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief The implicit material point solver in the previously converged
   * Lagrangian form (the paper's eq. 9-10).
   *
   * Each load step evaluates the basis once on the start-of-step grid,
   * numbers only the degrees of freedom that points touch, runs full Newton
   * with the consistent tangent, and then convects the points and re-sorts
   * them into cells and processes.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class MPMSolver
  {
  public:
    /**
     * @brief Set up the solver for a scene.
     * @param parameters The scene (with its bodies and their materials).
     * @param force_effects The loads the scene enables.
     * @param communicator The processes that share the work.
     */
    MPMSolver(const Parameters::All<dim>                    &parameters,
              std::vector<std::unique_ptr<ForceEffect<dim>>> force_effects,
              const MPI_Comm                                 communicator);

    /**
     * @brief Run all load steps, write output and the summary.
     */
    void
    run();

  private:
    /** Per-point data of one load step, in particle iteration order. */
    struct PointStep
    {
      /** Nodes, weights and gradients (fixed during the step). */
      PointSupport<dim> support;
      /** Local indices of the support's DoFs in the full vectors. */
      std::array<unsigned int, PointSupport<dim>::max_nodes * dim> dofs;
      /** Deformation gradient increment of the current iterate. */
      Tensor<2, dim> deformation_increment;
      /** Its inverse. */
      Tensor<2, dim> deformation_increment_inverse;
      /** Initial volume @f$V_p^0@f$. */
      double initial_volume;
      /** The point's material (of its body). */
      const Material *material;
      /** Constitutive result of the current iterate. */
      ConstitutiveUpdate update;
    };

    /**
     * Points with the same support DoFs: their stiffness is summed in one
     * dense local matrix and added to the system matrix once (fixed during
     * a load step).
     */
    struct AssemblyGroup
    {
      /** Indices into point_steps of the group's points. */
      std::vector<unsigned int> points;
      /** Positions in PointStep::dofs of the DoFs in the linear system,
       *  in the order of rows. */
      std::vector<unsigned int> local;
      /** Their indices in the linear system, ascending. */
      std::vector<types::global_dof_index> rows;
      /** For each DoF of the support, whether it is in the linear system. */
      std::vector<unsigned char> in_system;
    };

    /** A face penalty of ghost stabilisation, fixed during a load step. */
    struct FacePenalty
    {
      /** Local indices (full vectors) of both cells' DoFs. */
      std::vector<unsigned int> dofs;
      /** The penalty matrix on those DoFs. */
      FullMatrix<double> matrix;
    };

    /** Why a Newton solve stopped. */
    enum class NewtonOutcome
    {
      converged,
      iteration_limit,
      diverged,
      not_finite,
      inverted_point,
      increment_too_large
    };

    void
    make_grid();
    void
    setup_dofs();
    void
    create_material_points();
    void
    evaluate_basis();
    void
    number_system_dofs();
    void
    make_assembly_groups();
    void
    setup_ghost_penalty(const std::vector<bool> &touched);
    NewtonOutcome
    solve_load_step(const double         previous_load_factor,
                    const double         load_factor,
                    const unsigned int   load_step,
                    std::vector<double> &residuals);
    std::vector<MaterialPointInfo<dim>>
    point_infos() const;
    bool
    update_stresses();
    void
    assemble_external_force(const double load_factor);
    void
    assemble_residual();
    void
    assemble_matrix();
    void
    solve_linear_system(const bool estimate_condition);
    void
    compute_reactions();
    double
    max_point_increment() const;
    void
    update_material_points(const unsigned int load_step);
    double
    column_error(const double load_factor) const;
    void
    write_points(const double load_factor, const unsigned int load_step);
    std::vector<std::string>
    effect_descriptions() const;
    void
    measure_final_state();
    void
    write_summary(const double wall_time);
    void
    print_test_summary();

    const Parameters::All<dim>                          &parameters;
    const std::vector<std::unique_ptr<ForceEffect<dim>>> force_effects;
    /** The optional point properties of this scene. */
    PointLayout layout;

    /** The material of a point (from its body index, if several). */
    const Material &
    material_of(const ArrayView<const double> &properties) const
    {
      return *parameters
                .bodies[layout.body == PointLayout::absent ?
                          0 :
                          static_cast<unsigned int>(properties[layout.body])]
                .material;
    }
    const MPI_Comm     communicator;
    ConditionalOStream pcout;
    TimerOutput        timer;

    parallel::distributed::Triangulation<dim> triangulation;
    const MappingQ1<dim>                      mapping;
    const FESystem<dim>                       fe;
    DoFHandler<dim>                           dof_handler;
    AffineConstraints<double>                 constraints;
    IndexSet                                  locally_owned_dofs;
    IndexSet                                  locally_relevant_dofs;
    CartesianGrid<dim>                        grid;
    const BasisType                           basis_type;

    /** Local indices (in the full vectors) of each grid node's DoFs. */
    std::unordered_map<std::uint64_t, std::array<unsigned int, dim>> node_dofs;

    Particles::ParticleHandler<dim> material_points;
    std::vector<PointStep>          point_steps;
    /** The points grouped by support for the matrix assembly. */
    std::vector<AssemblyGroup> assembly_groups;
    /**
     * Updated Lagrangian form only: the gradients mapped to the current
     * configuration by the last residual assembly, reused by the matrix
     * assembly of the same iterate.
     */
    std::vector<std::array<Tensor<1, dim>, PointSupport<dim>::max_nodes>>
      mapped_gradients;

    /** Displacement increment of the step (full numbering, ghosted). */
    LinearAlgebra::distributed::Vector<double> increment;
    /** Internal and external nodal forces (full numbering). */
    LinearAlgebra::distributed::Vector<double> internal_force;
    LinearAlgebra::distributed::Vector<double> external_force;
    /** Index in the linear system of each local DoF, or invalid. */
    std::vector<types::global_dof_index> system_index;
    IndexSet                             system_owned;
    IndexSet                             system_relevant;
    TrilinosWrappers::SparseMatrix       system_matrix;
    TrilinosWrappers::MPI::Vector        system_rhs;
    TrilinosWrappers::MPI::Vector        system_solution;

    double residual_norm        = 0.;
    double external_force_norm  = 0.;
    double reference_force_norm = 0.;
    /** Prescribed DoFs (local index) and their displacement at full load. */
    std::vector<std::pair<unsigned int, double>> prescribed_dofs;

    /** Ghost stabilisation faces of the current load step. */
    std::vector<FacePenalty> ghost_faces;

    /** Owned constrained DoFs (local index) and their face * dim + comp. */
    std::vector<std::pair<unsigned int, unsigned int>> reaction_dofs;
    /** The (face * dim + component) pairs that carry reactions. */
    std::vector<unsigned int> reaction_columns;
    /** Reactions of the last converged step, by face * dim + component. */
    std::vector<double> reactions;
    /** Largest |sum of reactions + external force| / |external force|. */
    double max_reaction_imbalance = 0.;
    /** Worst condition estimate seen (0 if not estimated). */
    double worst_condition = 0.;
    /** Number of load-step cuts. */
    unsigned int n_cuts = 0;
    /** Number of converged load steps. */
    unsigned int accepted_load_steps = 0;
    /** Residual evaluations (stress updates) over the run. */
    unsigned int residual_evaluations = 0;
    /** Largest point displacement of an accepted step, in cells. */
    double largest_point_increment = 0.;
    /** Total mass of the points when they were created. */
    double initial_mass = 0.;

    /** Global measures of the final state, for the summaries. */
    struct FinalState
    {
      double     total_mass                  = 0.;
      double     max_tensile_vertical_stress = 0.;
      double     max_column_deviation        = 0.;
      Point<dim> initial_min, initial_max, final_min, final_max;
    } final_state;

    PointOutput<dim> point_output;
    std::ofstream    steps_file;
    std::ofstream    newton_file;

    unsigned int total_newton_iterations = 0;
    unsigned int n_system_dofs_last      = 0;
    double       last_error              = -1.;
    double       min_newton_order        = std::numeric_limits<double>::max();
    std::vector<std::string> test_lines;
  };
} // namespace impm

#endif
