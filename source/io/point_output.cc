#include <deal.II/base/utilities.h>

#include <impm/base/errors.h>
#include <impm/io/atomic_file.h>
#include <impm/io/free_space.h>
#include <impm/io/point_output.h>

#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>
#include <boost/serialization/vector.hpp>

#ifdef DEAL_II_WITH_HDF5
#  include <hdf5.h>
#endif

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace impm
{
  namespace
  {
#ifdef DEAL_II_WITH_HDF5
    /** One entry of HDF5's error stack: "function(): description". */
    herr_t
    collect_hdf5_error(unsigned int, const H5E_error2_t *error, void *data)
    {
      std::string entry = std::string(error->func_name) +
                          "(): " + (error->desc != nullptr ? error->desc : "");
      std::replace(entry.begin(), entry.end(), '\n', ' ');
      static_cast<std::vector<std::string> *>(data)->push_back(entry);
      return 0;
    }
#endif

    /**
     * @brief Why the last HDF5 call failed, in one line: the call the
     * library was asked for and the innermost cause (its error stack, whose
     * printing IMPM turns off); empty if the stack is empty. Clears it.
     */
    std::string
    hdf5_failure()
    {
      std::vector<std::string> entries;
#ifdef DEAL_II_WITH_HDF5
      H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, collect_hdf5_error, &entries);
      H5Eclear2(H5E_DEFAULT);
#endif
      if (entries.empty())
        return "";
      if (entries.size() == 1)
        return "HDF5: " + entries.front();
      return "HDF5: " + entries.front() + "; " + entries.back();
    }
  } // namespace



  template <int dim>
  PointOutput<dim>::PointOutput(
    const std::string                                &directory,
    const std::string                                &base_name,
    const Parameters::PointFileFormat                 format,
    const DataOutBase::VtkFlags::ZlibCompressionLevel compression,
    const MPI_Comm                                    communicator)
    : directory(directory)
    , base_name(base_name)
    , format(format)
    , communicator(communicator)
  {
    DataOutBase::VtkFlags vtk_flags;
    vtk_flags.compression_level = compression;
    this->set_flags(vtk_flags);
#ifdef DEAL_II_WITH_HDF5
    // HDF5 prints its error stack to stderr by default; a failed write is
    // reported in one line (hdf5_failure()).
    if (format == Parameters::PointFileFormat::hdf5)
      H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
#endif
  }



  template <int dim>
  void
  PointOutput<dim>::begin(const unsigned int              n_points,
                          const std::vector<std::string> &field_names,
                          const std::vector<bool>        &vector_flags)
  {
    names     = field_names;
    is_vector = vector_flags;
    patches.resize(n_points);
    for (unsigned int i = 0; i < n_points; ++i)
      {
        patches[i].patch_index = i;
        patches[i].data.reinit(names.size(), 1);
      }
  }



  template <int dim>
  void
  PointOutput<dim>::set_point(const unsigned int         index,
                              const Point<dim>          &position,
                              const std::vector<double> &values)
  {
    AssertDimension(values.size(), names.size());
    patches[index].vertices[0] = position;
    for (unsigned int c = 0; c < values.size(); ++c)
      patches[index].data(c, 0) = values[c];
  }



  template <int dim>
  void
  PointOutput<dim>::write(const double time, const unsigned int step)
  {
    const std::string stem =
      base_name + "_" + Utilities::int_to_string(step, 5);
    if (format == Parameters::PointFileFormat::hdf5)
      write_hdf5_files(time, stem);
    else
      write_vtu_files(time, stem);
  }



  template <int dim>
  void
  PointOutput<dim>::write_hdf5_files(const double time, const std::string &stem)
  {
    // All processes write their points into one file under a temporary
    // name; rank 0 renames it when all are done, then rewrites the series.
    // The file holds the nodes, a Polyvertex topology and one data set per
    // field (vector fields as one data set of dim components).
    const std::string          file      = stem + ".h5";
    const std::string          temporary = directory + "/" + file + ".tmp";
    DataOutBase::DataOutFilter filter(
      DataOutBase::DataOutFilterFlags(/*filter_duplicate_vertices=*/false,
                                      /*xdmf_hdf5_output=*/true));
    this->write_filtered_data(filter);
    // The file's size, known before it is written: every process checks
    // that it fits (space and file-size limit), so that a full disk stops
    // the run before HDF5 leaves a damaged file and its own error report.
    std::uintmax_t bytes = filter.n_nodes() * dim;
    for (unsigned int set = 0; set < filter.n_data_sets(); ++set)
      bytes += filter.n_nodes() * filter.get_data_set_dim(set);
    bytes = Utilities::MPI::sum(bytes * sizeof(double) +
                                  filter.n_cells() * sizeof(unsigned int),
                                communicator);
    const std::uintmax_t with_metadata = bytes + bytes / 10 + 65536;
    throw_if_any_failed(space_shortage(directory,
                                       with_metadata,
                                       with_metadata,
                                       "the point file " + directory + "/" +
                                         file),
                        communicator);
    try
      {
        this->write_hdf5_parallel(filter, temporary, communicator);
      }
    catch (const std::exception &exception)
      {
        // Collective: every process took part in the failed write.
        if (Utilities::MPI::this_mpi_process(communicator) == 0)
          std::remove(temporary.c_str());
        // HDF5's own reason; deal.II's (a generic input/output error) if
        // the stack is empty.
        const std::string hdf5 = hdf5_failure();
        throw CollectiveError(
          "Writing the file " + directory + "/" + file + " failed (" +
          (hdf5.empty() ? one_line_message(exception) : hdf5) + ").");
      }
    // The entry names the file as the series will find it.
    xdmf_entries.push_back(
      this->create_xdmf_entry(filter, file, time, communicator));
    const bool root = Utilities::MPI::this_mpi_process(communicator) == 0;
    run_collectively(communicator, [&]() {
      if (root)
        rename_or_throw(temporary, directory + "/" + file);
    });
    // The other parts (VTU files) get a .pvd series of their own.
    if (other_parts)
      run_collectively(communicator, [&]() {
        if (!root)
          return;
        add_other_parts(time, stem);
        write_series(base_name + "_parts.pvd");
      });
    const std::string series_file = directory + "/" + base_name + ".xdmf";
    this->write_xdmf_file(xdmf_entries, series_file + ".tmp", communicator);
    run_collectively(communicator, [&]() {
      if (root)
        rename_or_throw(series_file + ".tmp", series_file);
    });
  }



  template <int dim, int spacedim>
  std::string
  write_vtu_step(const DataOutInterface<dim, spacedim> &data,
                 const bool                             has_data,
                 const std::string                     &directory,
                 const std::string                     &stem,
                 const MPI_Comm                         communicator)
  {
    const unsigned int rank    = Utilities::MPI::this_mpi_process(communicator);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    const std::vector<unsigned int> with_data =
      Utilities::MPI::gather(communicator,
                             static_cast<unsigned int>(has_data),
                             0);
    const std::string piece =
      stem + "." + Utilities::int_to_string(rank, 4) + ".vtu";
    // All pieces exist before the record that names them.
    run_collectively(communicator, [&]() {
      if (has_data)
        write_file_atomically(directory + "/" + piece,
                              [&data](std::ostream &out) {
                                data.write_vtu(out);
                              });
    });
    run_collectively(communicator, [&]() {
      if (rank != 0)
        return;
      std::vector<std::string> pieces;
      for (unsigned int r = 0; r < n_ranks; ++r)
        if (with_data[r] > 0)
          pieces.push_back(stem + "." + Utilities::int_to_string(r, 4) +
                           ".vtu");
      write_file_atomically(directory + "/" + stem + ".pvtu",
                            [&](std::ostream &out) {
                              data.write_pvtu_record(out, pieces);
                            });
    });
    return stem + ".pvtu";
  }



  template <int dim>
  void
  PointOutput<dim>::write_vtu_files(const double time, const std::string &stem)
  {
    const std::string record =
      write_vtu_step(*this, !patches.empty(), directory, stem, communicator);
    run_collectively(communicator, [&]() {
      if (Utilities::MPI::this_mpi_process(communicator) == 0)
        {
          series.emplace_back(time, record);
          add_other_parts(time, stem);
          write_series(base_name + ".pvd");
        }
    });
  }



  template <int dim>
  void
  PointOutput<dim>::add_other_parts(const double time, const std::string &stem)
  {
    if (other_parts)
      for (const std::string &file : other_parts(stem.substr(base_name.size())))
        series.emplace_back(time, file);
  }



  template <int dim>
  void
  PointOutput<dim>::write_series(const std::string &file_name) const
  {
    write_file_atomically(directory + "/" + file_name, [&](std::ostream &out) {
      write_pvd_series(out, series);
    });
  }



  void
  write_pvd_series(std::ostream                                      &out,
                   const std::vector<std::pair<double, std::string>> &series)
  {
    // Files of one step are its parts 0, 1, ...
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" "
           "byte_order=\"LittleEndian\">\n"
        << "  <Collection>\n";
    unsigned int part = 0;
    for (unsigned int i = 0; i < series.size(); ++i)
      {
        part = (i > 0 && series[i].first == series[i - 1].first) ? part + 1 : 0;
        out << "    <DataSet timestep=\"" << std::setprecision(16)
            << series[i].first << "\" group=\"\" part=\"" << part
            << "\" file=\"" << series[i].second << "\"/>\n";
      }
    out << "  </Collection>\n</VTKFile>\n";
  }



  template <int dim>
  const std::vector<DataOutBase::Patch<0, dim>> &
  PointOutput<dim>::get_patches() const
  {
    return patches;
  }



  template <int dim>
  std::vector<std::string>
  PointOutput<dim>::get_dataset_names() const
  {
    return names;
  }



  template <int dim>
  std::vector<
    std::tuple<unsigned int,
               unsigned int,
               std::string,
               DataComponentInterpretation::DataComponentInterpretation>>
  PointOutput<dim>::get_nonscalar_data_ranges() const
  {
    std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
      ranges;
    for (unsigned int c = 0; c < names.size();)
      if (is_vector[c])
        {
          ranges.emplace_back(
            c,
            c + dim - 1,
            names[c],
            DataComponentInterpretation::component_is_part_of_vector);
          c += dim;
        }
      else
        ++c;
    return ranges;
  }



  template <int dim>
  void
  PointOutput<dim>::save(RunState &state, const std::string &key) const
  {
    std::vector<double> times;
    std::string         files;
    for (const auto &[time, file] : series)
      {
        times.push_back(time);
        files += file + "|";
      }
    state.set(key + ".times", times);
    state.set(key + ".files", files);
    std::ostringstream archive_text;
    {
      boost::archive::text_oarchive archive(archive_text);
      archive << xdmf_entries;
    }
    std::string text = archive_text.str();
    std::replace(text.begin(), text.end(), '\n', ' ');
    state.set(key + ".xdmf", text);
  }



  template <int dim>
  void
  PointOutput<dim>::load(const RunState &state, const std::string &key)
  {
    const auto         times = state.get_list(key + ".times");
    std::istringstream files(state.get_string(key + ".files"));
    series.clear();
    for (const double time : times)
      {
        std::string file;
        std::getline(files, file, '|');
        series.emplace_back(time, file);
      }
    std::istringstream            archive_text(state.get_string(key + ".xdmf"));
    boost::archive::text_iarchive archive(archive_text);
    archive >> xdmf_entries;
  }



#define IMPM_INSTANTIATE(DIM, SPACEDIM)                                        \
  template std::string write_vtu_step(const DataOutInterface<DIM, SPACEDIM> &, \
                                      const bool,                              \
                                      const std::string &,                     \
                                      const std::string &,                     \
                                      const MPI_Comm);
  IMPM_INSTANTIATE(0, 2)
  IMPM_INSTANTIATE(0, 3)
  IMPM_INSTANTIATE(2, 2)
  IMPM_INSTANTIATE(3, 3)
#undef IMPM_INSTANTIATE
  template class PointOutput<2>;
  template class PointOutput<3>;
} // namespace impm
