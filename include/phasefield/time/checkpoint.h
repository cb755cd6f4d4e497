#ifndef phasefield_time_checkpoint_h
#define phasefield_time_checkpoint_h

#include <deal.II/base/mpi.h>
#include <functional>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/parameters.h>
#include <phasefield/mesh/discretization.h>
#include <string>
#include <utility>
#include <vector>

namespace PhaseField
{
  /**
   * Checkpoints of the time loop. The checkpoint after step k is the
   * directory `checkpoint-<k>` of the output directory with
   *
   * - `mesh`, `mesh_fixed.data`, `mesh.info`: the p4est mesh with all
   *   fields (Discretization::save()), readable on any number of ranks;
   * - `state.txt`: the time-stepping state (CheckpointState), written by
   *   rank 0;
   * - `checkpoint.txt`: the parameters that give the state its meaning
   *   (Parameters: program, Dimension, levels, Epsilon, scheme, ...) and
   *   the size and checksum (64-bit FNV-1a) of each of the other files,
   *   written by rank 0 after they are complete; verify() checks them
   *   before a resume reads anything else.
   *
   * A checkpoint is written as `checkpoint-<k>.tmp` and renamed when it is
   * complete, and only then are older checkpoints deleted: a run killed
   * while writing leaves the previous checkpoint usable.
   */
  namespace Checkpoint
  {
    /** The time-stepping state of a checkpoint besides mesh and fields. */
    struct State
    {
      /** The last step taken; the run continues with step + 1. */
      unsigned int step = 0;
      /** The time after that step. */
      double time = 0;
      /**
       * The step size that the fields belong to (the nested scheme's P is
       * proportional to it), i.e. after any step halvings.
       */
      double state_tau = 0;
      /**
       * The largest size the next step may try (Newton / Regrow step
       * size; 0: the scheduled size).
       */
      double step_size_limit = 0;
      /** Number of fields (blocks of the state). */
      unsigned int n_fields = 0;
      /**
       * Number of those fields the mesh file holds: the phase field and
       * the fields a change of the mesh carries, in the order of the state
       * (TimeSteppingScheme::restores_after_remesh(): the scheme restores
       * the others after loading). Checkpoints written before this was
       * recorded hold all fields.
       */
      unsigned int n_stored_fields = 0;
      /** The records of solution.pvd so far (time, file). */
      std::vector<std::pair<double, std::string>> pvd_records;
      /**
       * The step before the first step of the run that wrote the
       * checkpoint (TimeLoop::continue_run(): the levels of a multilevel
       * schedule continue the step count; 0 otherwise).
       */
      unsigned int step_offset = 0;
      /**
       * Did that run end with this step before its last one
       * (TimeLoop::Client::finished(), the automatic level transition)?
       */
      bool finished = false;
      /**
       * The problem's own state (TimeLoop::Client::checkpoint_data();
       * shape from contour: the level and the energy history of the
       * automatic transition).
       */
      std::vector<double> problem_data;
    };

    /**
     * The parameters recorded in a checkpoint, as (`Subsection / Name`,
     * value) pairs; the first is the program (`Program`).
     */
    using Parameters = std::vector<std::pair<std::string, std::string>>;

    /**
     * @p value as a checkpoint records it: with all digits
     * (max_digits10), so that a resume compares it to the last bit.
     */
    std::string
    exact_value(const double value);

    /** @p values as exact_value()s separated by `, ` (a comma list). */
    std::string
    exact_values(const std::vector<double> &values);

    /**
     * The recorded parameters of the shape @p geometry, named in its
     * subsection (`Geometry` or `Target`): `Shape` and the numbers and
     * expression the shapes are made from (`Center`, `Second center`,
     * `Radius`, `Sizes`, `Expression`). For programs whose state keeps
     * its meaning only with its shape (edge restoration: the fixed
     * values; shape from contour: the target labeling).
     */
    Parameters
    geometry_parameters(const GeometryParameters &geometry);

    /**
     * Write the checkpoint of @p state (the fields on @p discretization),
     * @p time_stepping_state and @p parameters into @p directory and
     * delete the older ones there. First checks that the file system
     * has room for about twice the expected size and that no file would
     * exceed the process's file size limit (a full disk would end in an
     * abort inside p4est). Every file is read back after it is written:
     * the mesh files must have the sizes and headers of what
     * Discretization::save() writes (SavedFiles::check()), state.txt and
     * checkpoint.txt the size and checksum of their text, and then
     * @p read_back, called with the path of the complete checkpoint before
     * it replaces the previous one, must read it and throw unless it holds
     * what was written (@p state may be moved by then). A failed write
     * throws a WriteError naming the file on every rank, removes the
     * incomplete checkpoint and leaves the previous one as it is.
     * Collective.
     */
    template <int dim>
    void
    write(const std::string                              &directory,
          const Discretization<dim>                      &discretization,
          const BlockVector                              &state,
          const State                                    &time_stepping_state,
          const Parameters                               &parameters,
          const std::function<void(const std::string &)> &read_back);

    /**
     * Verify the checkpoint @p path before it is read: every file listed
     * in its `checkpoint.txt` must exist with the recorded size and
     * checksum (a missing, empty, truncated or changed file is an
     * InputError naming it), and every recorded parameter must have the
     * value in @p parameters, unless its name is in @p allowed_changes
     * (then a warning is printed). Throws InputError on every rank.
     * Returns on every rank whether an allowed change was found.
     * Collective.
     */
    bool
    verify(const std::string              &path,
           const Parameters               &parameters,
           const std::vector<std::string> &allowed_changes,
           const MPI_Comm                  mpi_communicator);

    /**
     * The path of the newest complete checkpoint in @p directory. Throws
     * InputError naming <Checkpoint / Resume> and @p directory on every
     * rank if there is none. Collective.
     */
    std::string
    find_last(const std::string &directory, const MPI_Comm mpi_communicator);

    /**
     * The time-stepping state of the checkpoint @p path (read on rank 0,
     * broadcast to all). Values that cannot belong to a checkpoint (step
     * before the step offset, a time or step size that is negative or not
     * finite) are an InputError naming the file. Collective.
     */
    State
    read_state(const std::string &path, const MPI_Comm mpi_communicator);

    /**
     * The base name of the mesh files of the checkpoint @p path, for
     * Discretization::load().
     */
    std::string
    mesh_filename(const std::string &path);

    /**
     * Delete every checkpoint (complete or not) in @p directory: a new
     * run must not leave one that a later resume would mistake for its
     * own. Collective.
     */
    void
    remove_all(const std::string &directory, const MPI_Comm mpi_communicator);
  } // namespace Checkpoint
} // namespace PhaseField

#endif
