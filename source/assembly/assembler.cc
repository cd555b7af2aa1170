#include <deal.II/base/mpi.h>

#include <impm/assembly/assembler.h>
#include <impm/mechanics/equilibrium_forms.h>
#include <impm/mechanics/point_stiffness.h>
#include <impm/mechanics/pulled_back_stress.h>

#include <Epetra_CrsMatrix.h>

#include <algorithm>
#include <memory>
#include <type_traits>

namespace impm
{
  template <int dim>
  Assembler<dim>::Assembler(
    const MaterialPoints<dim>                            &material_points,
    LoadStepSystem<dim>                                  &system,
    const std::vector<std::unique_ptr<ForceEffect<dim>>> &force_effects,
    const MPI_Comm                                        communicator)
    : material_points(material_points)
    , system(system)
    , force_effects(force_effects)
    , communicator(communicator)
  {}



  template <int dim>
  bool
  Assembler<dim>::update_stresses(const NodalVector &increment)
  {
    unsigned int       p          = 0;
    bool               admissible = true;
    const unsigned int hardening_index =
      material_points.layout().plastic_multiplier;
    for (const auto &point : material_points.particles())
      {
        PointStep<dim> &step = system.point_steps[p++];
        const auto     &s    = step.support;
        Tensor<2, dim>  dF   = unit_symmetric_tensor<dim>();
        for (unsigned int v = 0; v < s.n_nodes; ++v)
          for (unsigned int i = 0; i < dim; ++i)
            {
              const double du = increment.local_element(step.dofs[v * dim + i]);
              for (unsigned int j = 0; j < dim; ++j)
                dF[i][j] += du * s.gradients[v][j];
            }
        step.deformation_increment = dF;
        // An inverted or non-finite increment fails the Newton solve (and
        // lets the step control cut the step).
        const double jacobian = determinant(dF);
        if (!(jacobian > 0.) || !std::isfinite(jacobian))
          {
            admissible = false;
            continue;
          }
        step.deformation_increment_inverse = invert(dF);
        // So does an increment whose trial elastic strain is not positive
        // definite in floating point (a wild iterate: the model throws).
        try
          {
            step.material->update(PulledBackStress<dim>::embed(dF),
                                  PointState<dim>(point.get_properties())
                                    .elastic_left_cauchy_green(),
                                  hardening_index == PointLayout::absent ?
                                    0. :
                                    point.get_properties()[hardening_index],
                                  step.update);
          }
        catch (const ExceptionBase &)
          {
            admissible = false;
          }
      }
    return Utilities::MPI::min(admissible ? 1 : 0, communicator) == 1;
  }



  template <int dim>
  void
  Assembler<dim>::assemble_external_force(const double load_factor,
                                          NodalVector &external_force) const
  {
    external_force = 0.;
    if (!force_effects.empty())
      {
        const auto                  infos = material_points.infos();
        std::vector<Tensor<1, dim>> forces(infos.size());
        std::vector<FaceForce<dim>> face_forces;
        for (const auto &effect : force_effects)
          {
            effect->add_forces(infos, load_factor, forces);
            effect->add_face_forces(infos, load_factor, face_forces);
          }
        for (unsigned int p = 0; p < infos.size(); ++p)
          {
            const PointStep<dim> &step = system.point_steps[p];
            for (unsigned int v = 0; v < step.support.n_nodes; ++v)
              for (unsigned int i = 0; i < dim; ++i)
                external_force.local_element(step.dofs[v * dim + i]) +=
                  step.support.weights[v] * forces[p][i];
          }
        if (!face_forces.empty())
          {
            // The start-of-step positions and domains of the points.
            std::vector<std::pair<Point<dim>, Tensor<1, dim>>> domains;
            domains.reserve(infos.size());
            for (const auto &point : material_points.particles())
              domains.emplace_back(
                point.get_location(),
                PointState<dim>(point.get_properties()).domain_half_length());
            std::array<double, PointSupport<dim>::max_nodes> weights;
            for (const auto &face : face_forces)
              {
                const PointStep<dim> &step = system.point_steps[face.point];
                system.face_weights(face.point,
                                    domains[face.point].first,
                                    domains[face.point].second,
                                    face.axis,
                                    face.sign,
                                    weights);
                for (unsigned int v = 0; v < step.support.n_nodes; ++v)
                  for (unsigned int i = 0; i < dim; ++i)
                    external_force.local_element(step.dofs[v * dim + i]) +=
                      weights[v] * face.force[i];
              }
          }
      }
    external_force.compress(VectorOperation::add);
  }



  namespace
  {
    /**
     * @brief The assembler of one statement of equilibrium, @p Form
     * (PreviouslyConvergedForm or UpdatedLagrangianForm).
     */
    template <int dim, typename Form>
    class FormAssembler : public Assembler<dim>
    {
    public:
      /** The updated Lagrangian form maps the gradients to the current
       * configuration. */
      static constexpr bool maps_gradients =
        std::is_same_v<Form, UpdatedLagrangianForm<dim>>;

      /** @brief Constructor: see Assembler::create(). */
      FormAssembler(
        const MaterialPoints<dim>                            &material_points,
        LoadStepSystem<dim>                                  &system,
        const std::vector<std::unique_ptr<ForceEffect<dim>>> &force_effects,
        const MPI_Comm                                        communicator)
        : Assembler<dim>(material_points, system, force_effects, communicator)
      {}

      void
      add_internal_force(NodalVector &internal_force) override
      {
        auto &point_steps = this->system.point_steps;
        // The updated Lagrangian form keeps its mapped gradients for the
        // matrix of this iterate.
        if constexpr (maps_gradients)
          mapped_gradients.resize(point_steps.size());
        std::array<double, PointSupport<dim>::max_nodes * dim> forces;
        for (unsigned int p = 0; p < point_steps.size(); ++p)
          {
            const PointStep<dim> &step      = point_steps[p];
            const Tensor<1, dim> *gradients = step.support.gradients.data();
            if constexpr (maps_gradients)
              {
                Form::map_gradients(gradients,
                                    step.support.n_nodes,
                                    step.deformation_increment_inverse,
                                    mapped_gradients[p].data());
                gradients = mapped_gradients[p].data();
              }
            const Tensor<2, dim> stress =
              Form::force_stress(step.update,
                                 step.deformation_increment_inverse,
                                 step.initial_volume);
            const unsigned int n = step.support.n_nodes * dim;
            std::fill(forces.begin(), forces.begin() + n, 0.);
            add_point_forces(stress,
                             gradients,
                             step.support.n_nodes,
                             forces.data());
            for (unsigned int k = 0; k < n; ++k)
              internal_force.local_element(step.dofs[k]) += forces[k];
          }
      }

      void
      add_stiffness(TrilinosWrappers::SparseMatrix &matrix) const override
      {
        const auto &point_steps = this->system.point_steps;
        // One support's dense matrix (52 kB in 3D): on the heap.
        const auto stiffness = std::make_unique<PointStiffness<dim>>();
        std::array<double, PointStiffness<dim>::max_dofs> row_values;
        for (const AssemblyGroup &group : this->system.assembly_groups)
          {
            // The group's matrix over all its support's DoFs; the rows and
            // columns in the linear system are picked when it is added.
            const bool symmetric = std::all_of(
              group.points.begin(),
              group.points.end(),
              [&](const unsigned int p) {
                return point_steps[p].material->has_symmetric_tangent();
              });
            stiffness->reset(point_steps[group.points.front()].support.n_nodes,
                             symmetric ? TangentSymmetry::major :
                                         TangentSymmetry::general);
            for (const unsigned int p : group.points)
              {
                const PointStep<dim> &step = point_steps[p];
                const Tensor<1, dim> *gradients =
                  maps_gradients ? mapped_gradients[p].data() :
                                   step.support.gradients.data();
                stiffness->add(Form::tangent(*step.material,
                                             step.update,
                                             step.deformation_increment_inverse,
                                             step.initial_volume),
                               gradients,
                               group.in_system.data());
              }
            add_to_matrix(group, *stiffness, matrix, row_values);
          }
      }

    private:
      /**
       * Add the group's rows and columns of @p stiffness to @p matrix. Rows
       * this process owns are added in place: the group's columns, sorted
       * by their local index, are found by one merge walk along the
       * matrix's sorted row (instead of a binary search and a global-to-
       * local lookup per entry, which cost 40 % of the 3D collapse's run
       * time). Rows of other processes go through the matrix's add().
       */
      static void
      add_to_matrix(
        const AssemblyGroup                               &group,
        const PointStiffness<dim>                         &stiffness,
        TrilinosWrappers::SparseMatrix                    &matrix,
        std::array<double, PointStiffness<dim>::max_dofs> &row_values)
      {
        // The values are changed through the row views of the (const)
        // matrix deal.II exposes.
        const Epetra_CrsMatrix &epetra = matrix.trilinos_matrix();
        const unsigned int      n      = group.rows.size();
        // The group's columns in the matrix's local numbering, sorted.
        std::array<std::pair<int, unsigned int>, PointStiffness<dim>::max_dofs>
          columns;
        for (unsigned int b = 0; b < n; ++b)
          columns[b] = {epetra.LCID(static_cast<int>(group.rows[b])), b};
        std::sort(columns.begin(), columns.begin() + n);
        std::array<int, PointStiffness<dim>::max_dofs> positions;
        bool                                           have_positions   = false;
        int                                            positions_length = 0;
        for (unsigned int a = 0; a < n; ++a)
          {
            const int local_row = epetra.LRID(static_cast<int>(group.rows[a]));
            if (local_row < 0)
              {
                for (unsigned int b = 0; b < n; ++b)
                  row_values[b] =
                    stiffness.entry(group.local[a], group.local[b]);
                matrix.add(group.rows[a],
                           n,
                           group.rows.data(),
                           row_values.data(),
                           /*elide_zero_values=*/false,
                           /*col_indices_are_sorted=*/true);
                continue;
              }
            int     length  = 0;
            double *values  = nullptr;
            int    *indices = nullptr;
            epetra.ExtractMyRowView(local_row, length, values, indices);
            // The rows of one node's components have the same columns:
            // the previous row's positions are tried first.
            bool known = have_positions && length == positions_length;
            for (unsigned int c = 0; c < n && known; ++c)
              known = indices[positions[c]] == columns[c].first;
            if (!known)
              {
                int position = 0;
                for (unsigned int c = 0; c < n; ++c)
                  {
                    while (position < length &&
                           indices[position] < columns[c].first)
                      ++position;
                    // Checked in release builds too: an entry missing from
                    // the sparsity pattern must not become a write past
                    // the row.
                    AssertThrow(position < length &&
                                  indices[position] == columns[c].first,
                                ExcMessage("The stiffness of a material point "
                                           "has an entry outside the "
                                           "system's sparsity pattern."));
                    positions[c] = position;
                  }
                have_positions   = true;
                positions_length = length;
              }
            const unsigned int row = group.local[a];
            for (unsigned int c = 0; c < n; ++c)
              values[positions[c]] +=
                stiffness.entry(row, group.local[columns[c].second]);
          }
      }

    private:
      /**
       * Updated Lagrangian form only: the gradients mapped by the last
       * internal-force assembly, reused by the matrix of the same iterate.
       */
      std::vector<std::array<Tensor<1, dim>, PointSupport<dim>::max_nodes>>
        mapped_gradients;
    };
  } // namespace



  template <int dim>
  std::unique_ptr<Assembler<dim>>
  Assembler<dim>::create(
    const Parameters::Formulation                         formulation,
    const MaterialPoints<dim>                            &material_points,
    LoadStepSystem<dim>                                  &system,
    const std::vector<std::unique_ptr<ForceEffect<dim>>> &force_effects,
    const MPI_Comm                                        communicator)
  {
    switch (formulation)
      {
        case Parameters::Formulation::updated_lagrangian:
          return std::make_unique<
            FormAssembler<dim, UpdatedLagrangianForm<dim>>>(material_points,
                                                            system,
                                                            force_effects,
                                                            communicator);
        default:
          return std::make_unique<
            FormAssembler<dim, PreviouslyConvergedForm<dim>>>(material_points,
                                                              system,
                                                              force_effects,
                                                              communicator);
      }
  }



  template class Assembler<2>;
  template class Assembler<3>;
} // namespace impm
