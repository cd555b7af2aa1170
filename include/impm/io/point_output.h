#ifndef impm_io_point_output_h
#define impm_io_point_output_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <impm/core/parameters.h>
#include <impm/io/run_state.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief Write one output step of a VTU series: each process with data
   * (@p has_data) writes its piece `<stem>.<rank>.vtu` of @p data (under a
   * temporary name, then renamed; a process without data writes none: an
   * empty piece is not valid VTK), then rank 0 writes the record
   * `<stem>.pvtu` naming the pieces. A process that cannot write stops all
   * (run_collectively()). Collective; returns the record's file name.
   */
  template <int dim, int spacedim>
  std::string
  write_vtu_step(const DataOutInterface<dim, spacedim> &data,
                 const bool                             has_data,
                 const std::string                     &directory,
                 const std::string                     &stem,
                 const MPI_Comm                         communicator);

  /**
   * @brief Write the `.pvd` record of a series of (time, file) pairs in
   * their order: consecutive files of one time are the parts 0, 1, ... of
   * its step; times to 16 digits.
   */
  void
  write_pvd_series(std::ostream                                      &out,
                   const std::vector<std::pair<double, std::string>> &series);

  /**
   * @brief Writes material points with their fields for ParaView: as `.vtu`
   * pieces, a `.pvtu` record per output step and a `.pvd` time series, or
   * as one `.h5` file per output step (parallel HDF5, all processes into
   * one file) and an `.xdmf` time series.
   *
   * The caller adds the points of this process and the fields to write;
   * only what is added is computed and written. Every file is written under
   * a temporary name and renamed when complete, so a run that stops never
   * leaves a half-written record behind.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class PointOutput : public DataOutInterface<0, dim>
  {
  public:
    /**
     * @brief Constructor.
     * @param directory Output directory (must exist).
     * @param base_name File names start with this.
     * @param format The file format.
     * @param compression The zlib level of the VTU files' data.
     * @param communicator The processes that write together.
     */
    PointOutput(const std::string                                &directory,
                const std::string                                &base_name,
                const Parameters::PointFileFormat                 format,
                const DataOutBase::VtkFlags::ZlibCompressionLevel compression,
                const MPI_Comm                                    communicator);

    /**
     * @brief Start a new output step with @p n_points points on this process
     * and the given field layout.
     *
     * @param n_points The points of this process.
     * @param names One name per scalar component; vector fields repeat their
     *   name for each component.
     * @param is_vector Whether each component is part of a vector field.
     */
    void
    begin(const unsigned int              n_points,
          const std::vector<std::string> &names,
          const std::vector<bool>        &is_vector);

    /**
     * @brief Set the position and field values of point @p index.
     */
    void
    set_point(const unsigned int         index,
              const Point<dim>          &position,
              const std::vector<double> &values);

    /**
     * @brief Write this step's files and add them to the `.pvd` series.
     * @param time The pseudo-time (load factor) of the step.
     * @param step The output step number (used in the file names).
     */
    void
    write(const double time, const unsigned int step);

  private:
    const std::vector<DataOutBase::Patch<0, dim>> &
    get_patches() const override;

    std::vector<std::string>
    get_dataset_names() const override;

    std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
    get_nonscalar_data_ranges() const override;

    /** @brief write() for the vtu format. */
    void
    write_vtu_files(const double time, const std::string &stem);

    /** @brief Add the files other_parts() writes for the output step
     *  @p stem to the series at @p time (rank 0). */
    void
    add_other_parts(const double time, const std::string &stem);

    /** @brief Write the series as the `.pvd` file @p file_name in the
     *  output directory (rank 0). */
    void
    write_series(const std::string &file_name) const;

    /** @brief write() for the hdf5 format. */
    void
    write_hdf5_files(const double time, const std::string &stem);

    const std::string                       directory;
    const std::string                       base_name;
    const Parameters::PointFileFormat       format;
    const MPI_Comm                          communicator;
    std::vector<DataOutBase::Patch<0, dim>> patches;
    std::vector<std::string>                names;
    std::vector<bool>                       is_vector;

  public:
    /**
     * @brief Files of other parts of the scene to add to each step of the
     * `.pvd` series beside the points: called on rank 0 with the step's
     * file suffix ("_00040"), it writes its files (VTU) into the output
     * directory and returns their names. ParaView shows them as the parts
     * 1, 2, ... of each step. With HDF5 point files (an `.xdmf` series)
     * they form a `.pvd` series of their own, `<base name>_parts.pvd`.
     */
    std::function<std::vector<std::string>(const std::string &suffix)>
      other_parts;

    /** @brief Save the series written so far (the records behind the
     *  `.pvd` or `.xdmf` file) into @p state under @p key. */
    void
    save(RunState &state, const std::string &key) const;

    /** @brief Continue the series saved by save(). */
    void
    load(const RunState &state, const std::string &key);

  private:
    /** The vtu series: load factor and record. */
    std::vector<std::pair<double, std::string>> series;
    /** The hdf5 series. */
    std::vector<XDMFEntry> xdmf_entries;
  };
} // namespace impm

#endif
