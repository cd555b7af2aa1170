#include <deal.II/base/array_view.h>

#include <impm/system/assembly_groups.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>

namespace impm
{
  namespace
  {
    /**
     * The points of one support: positions [first, last) of an order of
     * the points, and the run whose group they join (themselves if none).
     */
    struct SupportRun
    {
      unsigned int first, last, target;
    };



    /** A box of grid nodes: its lowest and highest node per direction. */
    template <int dim>
    using NodeBox =
      std::pair<std::array<unsigned int, dim>, std::array<unsigned int, dim>>;

    /** A key of @p box: its lowest node and its widths. */
    template <int dim>
    std::uint64_t
    node_box_key(const CartesianGrid<dim> &cartesian, const NodeBox<dim> &box)
    {
      std::uint64_t key = cartesian.node_index(box.first);
      for (unsigned int d = 0; d < dim; ++d)
        key = 3 * key + (box.second[d] - box.first[d]);
      return key;
    }



    /**
     * Order the points by support, largest first (ties by index), into @p
     * order, and cut the order into runs of one support.
     */
    template <int dim>
    std::vector<SupportRun>
    support_runs(const PointSteps<dim>     &point_steps,
                 std::vector<unsigned int> &order)
    {
      order.resize(point_steps.size());
      std::iota(order.begin(), order.end(), 0u);
      const auto same_support = [&](const unsigned int a,
                                    const unsigned int b) {
        const PointStep<dim> &x = point_steps[a], &y = point_steps[b];
        return x.support.n_nodes == y.support.n_nodes &&
               std::equal(x.dofs.begin(),
                          x.dofs.begin() + x.support.n_nodes * dim,
                          y.dofs.begin());
      };
      std::sort(order.begin(),
                order.end(),
                [&](const unsigned int a, const unsigned int b) {
                  const PointStep<dim> &x = point_steps[a], &y = point_steps[b];
                  if (x.support.n_nodes != y.support.n_nodes)
                    return x.support.n_nodes > y.support.n_nodes;
                  const unsigned int n = x.support.n_nodes * dim;
                  for (unsigned int k = 0; k < n; ++k)
                    if (x.dofs[k] != y.dofs[k])
                      return x.dofs[k] < y.dofs[k];
                  return a < b;
                });
      std::vector<SupportRun> runs;
      for (unsigned int first = 0; first < order.size();)
        {
          unsigned int last = first + 1;
          while (last < order.size() && same_support(order[first], order[last]))
            ++last;
          const unsigned int run = runs.size();
          runs.push_back({first, last, run});
          first = last;
        }
      return runs;
    }



    /**
     * The run whose box is the largest box of at most 3 nodes per direction
     * that holds run @p r's box (@p r itself if none), following the runs
     * already joined (runs come largest first).
     */
    template <int dim>
    unsigned int
    largest_container(
      const unsigned int                                         r,
      const std::vector<NodeBox<dim>>                           &boxes,
      const std::vector<std::pair<std::uint64_t, unsigned int>> &run_of_box,
      const std::vector<SupportRun>                             &runs,
      const PointSteps<dim>                                     &point_steps,
      const std::vector<unsigned int>                           &order,
      const CartesianGrid<dim>                                  &cartesian)
    {
      using Box          = NodeBox<dim>;
      const auto box_key = [&](const Box &box) {
        return node_box_key<dim>(cartesian, box);
      };
      // The boxes of up to 3 nodes per direction that hold this one:
      // per direction, the lowest node may go down and the highest up,
      // to a width of at most 3 (each combination of these widenings).
      unsigned int best = r,
                   best_nodes =
                     point_steps[order[runs[r].first]].support.n_nodes;
      // (At most 6 per direction: a box of one node widened by 0 to 2.)
      std::array<std::array<std::pair<unsigned int, unsigned int>, 6>, dim>
                                    widenings;
      std::array<unsigned int, dim> n_widenings;
      unsigned int                  n_candidates = 1;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const unsigned int width = boxes[r].second[d] - boxes[r].first[d];
          n_widenings[d]           = 0;
          for (unsigned int down = 0; down <= 2 - width; ++down)
            for (unsigned int up = 0; down + up <= 2 - width; ++up)
              if (boxes[r].first[d] >= down)
                widenings[d][n_widenings[d]++] = {down, up};
          n_candidates *= n_widenings[d];
        }
      // Candidate 0 widens nothing: the box itself.
      for (unsigned int code = 1; code < n_candidates; ++code)
        {
          Box          candidate = boxes[r];
          unsigned int c         = code;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const auto [down, up] = widenings[d][c % n_widenings[d]];
              c /= n_widenings[d];
              candidate.first[d] -= down;
              candidate.second[d] += up;
            }
          const auto found =
            std::lower_bound(run_of_box.begin(),
                             run_of_box.end(),
                             std::make_pair(box_key(candidate), 0u));
          if (found == run_of_box.end() || found->first != box_key(candidate))
            continue;
          const unsigned int container = runs[found->second].target;
          const unsigned int nodes =
            point_steps[order[runs[container].first]].support.n_nodes;
          if (nodes > best_nodes)
            {
              best       = container;
              best_nodes = nodes;
            }
        }
      return best;
    }



    /**
     * Add to @p groups the group of the points of the runs @p members of
     * @p runs (of @p order), which share one target.
     */
    template <int dim>
    void
    add_group(const PointSteps<dim>                      &point_steps,
              const std::vector<types::global_dof_index> &index_in_system,
              const std::vector<unsigned int>            &order,
              const std::vector<SupportRun>              &runs,
              const ArrayView<const unsigned int>        &members,
              std::vector<AssemblyGroup>                 &groups)
    {
      const unsigned int target = runs[members[0]].target;
      AssemblyGroup     &group  = groups.emplace_back();
      // The points in index order, so that the order of summation within a
      // group is that of the points.
      for (const unsigned int r : members)
        group.points.insert(group.points.end(),
                            order.begin() + runs[r].first,
                            order.begin() + runs[r].last);
      std::sort(group.points.begin(), group.points.end());

      // The group's support is that of its first run, which holds the
      // others': each point's nodes by their position in it.
      const PointStep<dim> &step  = point_steps[order[runs[target].first]];
      const auto           &nodes = step.support.nodes;
      group.n_nodes               = step.support.n_nodes;
      group.dofs.assign(step.dofs.begin(),
                        step.dofs.begin() + group.n_nodes * dim);
      // One run: every point has the group's support.
      if (members.size() > 1)
        for (const unsigned int p : group.points)
          {
            const PointSupport<dim> &support = point_steps[p].support;
            for (unsigned int v = 0; v < support.n_nodes; ++v)
              group.node_positions.push_back(static_cast<unsigned char>(
                std::find(nodes.begin(),
                          nodes.begin() + group.n_nodes,
                          support.nodes[v]) -
                nodes.begin()));
          }

      std::vector<std::pair<types::global_dof_index, unsigned int>> entries;
      for (unsigned int k = 0; k < group.n_nodes * dim; ++k)
        if (index_in_system[group.dofs[k]] != numbers::invalid_dof_index)
          entries.emplace_back(index_in_system[group.dofs[k]], k);
      std::sort(entries.begin(), entries.end());
      group.in_system.assign(group.n_nodes * dim, 0);
      for (const auto &[row, k] : entries)
        {
          group.rows.push_back(row);
          group.local.push_back(k);
          group.in_system[k] = 1;
        }
      // Points whose every DoF is constrained add nothing to the matrix.
      if (group.rows.empty())
        groups.pop_back();
    }
  } // namespace



  template <int dim>
  std::vector<AssemblyGroup>
  make_assembly_groups(
    const PointSteps<dim>                      &point_steps,
    const std::vector<types::global_dof_index> &index_in_system,
    const CartesianGrid<dim>                   &cartesian)
  {
    std::vector<unsigned int> order;
    std::vector<SupportRun>   runs = support_runs(point_steps, order);

    // A support is a box of nodes (a GIMP point's spans at most 3 per
    // direction). A run whose box lies in the box of a larger run joins
    // it: its points' stiffness is added to that block, the missing nodes
    // as zero gradients.
    using Box          = NodeBox<dim>;
    const auto box_key = [&](const Box &box) {
      return node_box_key<dim>(cartesian, box);
    };
    std::vector<Box>                                    boxes(runs.size());
    std::vector<std::pair<std::uint64_t, unsigned int>> run_of_box;
    std::vector<bool>                                   is_box(runs.size());
    for (unsigned int r = 0; r < runs.size(); ++r)
      {
        const PointSupport<dim> &support =
          point_steps[order[runs[r].first]].support;
        Box &box = boxes[r];
        box.first.fill(std::numeric_limits<unsigned int>::max());
        box.second.fill(0);
        for (unsigned int v = 0; v < support.n_nodes; ++v)
          {
            std::uint64_t index = support.nodes[v];
            for (unsigned int d = 0; d < dim; ++d)
              {
                const unsigned int i = index % cartesian.n_nodes(d);
                index /= cartesian.n_nodes(d);
                box.first[d]  = std::min(box.first[d], i);
                box.second[d] = std::max(box.second[d], i);
              }
          }
        unsigned int n_in_box = 1;
        bool         narrow   = true;
        for (unsigned int d = 0; d < dim; ++d)
          {
            n_in_box *= box.second[d] - box.first[d] + 1;
            narrow = narrow && box.second[d] - box.first[d] <= 2;
          }
        is_box[r] = narrow && n_in_box == support.n_nodes;
        if (is_box[r])
          run_of_box.emplace_back(box_key(box), r);
      }
    std::sort(run_of_box.begin(), run_of_box.end());
    // Runs come largest first, so a run's container has found its own
    // (the largest box holding it) before.
    for (unsigned int r = 0; r < runs.size(); ++r)
      {
        if (!is_box[r])
          continue;
        runs[r].target = largest_container<dim>(
          r, boxes, run_of_box, runs, point_steps, order, cartesian);
      }
    // The runs of each group: by target, each target first.
    std::vector<unsigned int> by_target(runs.size());
    std::iota(by_target.begin(), by_target.end(), 0u);
    std::stable_sort(by_target.begin(),
                     by_target.end(),
                     [&](const unsigned int a, const unsigned int b) {
                       return runs[a].target < runs[b].target;
                     });
    std::vector<AssemblyGroup> groups;
    for (unsigned int first = 0; first < by_target.size();)
      {
        unsigned int last = first + 1;
        while (last < by_target.size() &&
               runs[by_target[last]].target == runs[by_target[first]].target)
          ++last;
        add_group(point_steps,
                  index_in_system,
                  order,
                  runs,
                  ArrayView<const unsigned int>(by_target.data() + first,
                                                last - first),
                  groups);
        first = last;
      }
    return groups;
  }



  template std::vector<AssemblyGroup>
  make_assembly_groups(const PointSteps<2> &,
                       const std::vector<types::global_dof_index> &,
                       const CartesianGrid<2> &);
  template std::vector<AssemblyGroup>
  make_assembly_groups(const PointSteps<3> &,
                       const std::vector<types::global_dof_index> &,
                       const CartesianGrid<3> &);
} // namespace impm
