// The rigid bodies' motion in RigidContact: the force-driven components
// as unknowns of the Newton solve (their residual, the coupling blocks
// of the bordered matrix, the update, the checkpoint) and each body's
// displacement for output and at the start and end of an attempt
// (move_bodies). The probes and their forces are in
// rigid_contact.cc.
#include <impm/base/names.h>
#include <impm/contact/rigid_contact.h>
#include <impm/system/load_step_system.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace impm
{
  template <int dim>
  Vector<double>
  RigidContact<dim>::unknown_residuals() const
  {
    Vector<double> residuals(body_unknowns.size());
    for (unsigned int j = 0; j < body_unknowns.size(); ++j)
      residuals[j] =
        force_on_material[body_unknowns[j].body][body_unknowns[j].component];
    Utilities::MPI::sum(residuals,
                        grid.get_triangulation().get_communicator(),
                        residuals);
    for (unsigned int j = 0; j < body_unknowns.size(); ++j)
      residuals[j] =
        applied_force[body_unknowns[j].body][body_unknowns[j].component] -
        residuals[j];
    return residuals;
  }



  template <int dim>
  double
  RigidContact<dim>::applied_force_norm() const
  {
    double sum = 0.;
    for (const Unknown &unknown : body_unknowns)
      sum += std::pow(applied_force[unknown.body][unknown.component], 2);
    return std::sqrt(sum);
  }



  template <int dim>
  void
  RigidContact<dim>::add_coupling(const LoadStepSystem<dim> &system,
                                  std::vector<NodalVector>  &columns,
                                  std::vector<NodalVector>  &rows,
                                  FullMatrix<double>        &corner) const
  {
    const unsigned int m = body_unknowns.size();
    columns.resize(m);
    rows.resize(m);
    for (unsigned int j = 0; j < m; ++j)
      {
        grid.reinit_vector(columns[j]);
        grid.reinit_vector(rows[j]);
      }
    corner.reinit(m, m);
    // Unknowns of each body.
    std::vector<std::vector<unsigned int>> of_body(rigid_bodies.size());
    for (unsigned int j = 0; j < m; ++j)
      of_body[body_unknowns[j].body].push_back(j);
    for (const Probe &probe : probes)
      {
        if (!probe.active || of_body[probe.body].empty())
          continue;
        // The probe's force f depends on x - w (x the face's position, w
        // the body's displacement): df/dw = -df/dx = -A.
        const Tensor<2, dim> &A    = probe.force_derivative;
        const PointStep<dim> &step = system.point_steps[probe.point];
        for (const unsigned int j : of_body[probe.body])
          {
            const unsigned int c = body_unknowns[j].component;
            // Internal force -N^T f: derivative N^T A e_c. Its force sum
            // f_c: derivative e_c^T A N.
            for (unsigned int v = 0; v < step.support.n_nodes; ++v)
              for (unsigned int i = 0; i < dim; ++i)
                {
                  const auto dof = step.dofs[v * dim + i];
                  columns[j].local_element(dof) += probe.weights[v] * A[i][c];
                  rows[j].local_element(dof) += probe.weights[v] * A[c][i];
                }
            for (const unsigned int k : of_body[probe.body])
              corner(j, k) -= A[c][body_unknowns[k].component];
          }
      }
    for (unsigned int j = 0; j < m; ++j)
      {
        columns[j].compress(VectorOperation::add);
        rows[j].compress(VectorOperation::add);
      }
    Utilities::MPI::sum(corner,
                        grid.get_triangulation().get_communicator(),
                        corner);
  }



  template <int dim>
  void
  RigidContact<dim>::add_to_unknowns(const Vector<double> &correction)
  {
    for (unsigned int j = 0; j < body_unknowns.size(); ++j)
      {
        const auto &[body, component] = body_unknowns[j];
        displacement[body][component] += correction[j];
        displacement_increment[body][component] += correction[j];
      }
  }



  template <int dim>
  double
  RigidContact<dim>::max_unknown_increment() const
  {
    double largest = 0.;
    for (const auto &[body, component] : body_unknowns)
      largest = std::max(largest,
                         std::abs(displacement_increment[body][component]) /
                           grid.cartesian().cell_size[component]);
    return largest;
  }



  template <int dim>
  Tensor<1, dim>
  RigidContact<dim>::displacement_of(const unsigned int k,
                                     const double       load_factor) const
  {
    return rigid_bodies[k].displacement_at(load_factor) + accepted_unknowns[k];
  }



  template <int dim>
  void
  RigidContact<dim>::save(RunState &state) const
  {
    for (unsigned int j = 0; j < body_unknowns.size(); ++j)
      state.set(
        "contact.unknown " + std::to_string(j),
        accepted_unknowns[body_unknowns[j].body][body_unknowns[j].component]);
  }



  template <int dim>
  void
  RigidContact<dim>::load(const RunState &state)
  {
    for (unsigned int j = 0; j < body_unknowns.size(); ++j)
      accepted_unknowns[body_unknowns[j].body][body_unknowns[j].component] =
        state.get_double("contact.unknown " + std::to_string(j));
  }



  template <int dim>
  std::vector<std::pair<Point<dim>, Point<dim>>>
  RigidContact<dim>::move_bodies(const double start,
                                 const double target,
                                 const double largest_cell)
  {
    // A body pushed by a force starts the attempt where the last step
    // left it, and may move about a cell more within it (the step control
    // cuts a step that moves it further).
    std::vector<std::pair<Point<dim>, Point<dim>>> reach;
    for (unsigned int b = 0; b < rigid_bodies.size(); ++b)
      {
        const auto &body = rigid_bodies[b];
        start_displacement[b] =
          body.displacement_at(start) + accepted_unknowns[b];
        displacement[b] = body.displacement_at(target) + accepted_unknowns[b];
        displacement_increment[b] = displacement[b] - start_displacement[b];
        applied_force[b]          = target * body.force;
        rotation[b]               = body.rotation_at(target);
        start_rotation[b]         = body.rotation_at(start);
        rotation_increment[b]     = rotation[b] * transpose(start_rotation[b]);
        const double margin =
          (body.force_components.empty() ? 1. : 2.) * largest_cell;
        auto       box   = body.bounding_box(displacement[b], target);
        const auto other = body.bounding_box(start_displacement[b], start);
        for (unsigned int d = 0; d < dim; ++d)
          {
            box.first[d]  = std::min(box.first[d], other.first[d]) - margin;
            box.second[d] = std::max(box.second[d], other.second[d]) + margin;
          }
        reach.push_back(box);
      }
    return reach;
  }



  // The members defined here, for both dimensions (the class's other
  // members are instantiated in rigid_contact.cc).
  template <int dim>
  double
  RigidContact<dim>::reference_force() const
  {
    return body_unknowns.empty() ? 0. : applied_force_norm();
  }



  template <int dim>
  unsigned int
  RigidContact<dim>::n_global_unknowns() const
  {
    return body_unknowns.size();
  }



  template <int dim>
  Vector<double>
  RigidContact<dim>::global_residuals() const
  {
    return unknown_residuals();
  }



  template <int dim>
  void
  RigidContact<dim>::global_coupling(const LoadStepSystem<dim> &system,
                                     std::vector<NodalVector>  &columns,
                                     std::vector<NodalVector>  &rows,
                                     FullMatrix<double>        &corner) const
  {
    add_coupling(system, columns, rows, corner);
  }



  template <int dim>
  void
  RigidContact<dim>::add_to_global_unknowns(const Vector<double> &correction)
  {
    add_to_unknowns(correction);
  }



  template <int dim>
  std::string
  RigidContact<dim>::unbalanced_unknown(const unsigned int j) const
  {
    return rigid_bodies[body_unknowns[j].body].name +
           " is pushed by its force in " +
           Names::axis(body_unknowns[j].component) +
           " but touches no material there: nothing balances the force "
           "(place the body on the material)";
  }



#define IMPM_INSTANTIATE(dim)                                                  \
  template std::vector<std::pair<Point<dim>, Point<dim>>>                      \
  RigidContact<dim>::move_bodies(const double, const double, const double);    \
  template Vector<double> RigidContact<dim>::unknown_residuals() const;        \
  template double         RigidContact<dim>::applied_force_norm() const;       \
  template void   RigidContact<dim>::add_coupling(const LoadStepSystem<dim> &, \
                                                std::vector<NodalVector> &,  \
                                                std::vector<NodalVector> &,  \
                                                FullMatrix<double> &) const; \
  template void   RigidContact<dim>::add_to_unknowns(const Vector<double> &);  \
  template double RigidContact<dim>::max_unknown_increment() const;            \
  template Tensor<1, dim> RigidContact<dim>::displacement_of(                  \
    const unsigned int, const double) const;                                   \
  template void           RigidContact<dim>::save(RunState &) const;           \
  template void           RigidContact<dim>::load(const RunState &);           \
  template double         RigidContact<dim>::reference_force() const;          \
  template unsigned int   RigidContact<dim>::n_global_unknowns() const;        \
  template Vector<double> RigidContact<dim>::global_residuals() const;         \
  template void           RigidContact<dim>::global_coupling(                  \
    const LoadStepSystem<dim> &,                                     \
    std::vector<NodalVector> &,                                      \
    std::vector<NodalVector> &,                                      \
    FullMatrix<double> &) const;                                     \
  template void RigidContact<dim>::add_to_global_unknowns(                     \
    const Vector<double> &);                                                   \
  template std::string RigidContact<dim>::unbalanced_unknown(                  \
    const unsigned int) const;
  IMPM_INSTANTIATE(2)
  IMPM_INSTANTIATE(3)
#undef IMPM_INSTANTIATE
} // namespace impm
