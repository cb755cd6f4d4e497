#ifndef phasefield_mesh_discretization_h
#define phasefield_mesh_discretization_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/numerics/vector_tools_common.h>
#include <phasefield/core/linear_algebra.h>
#include <phasefield/core/parameters.h>
#include <phasefield/mesh/lumped_operators.h>
#include <string>
#include <utility>
#include <vector>

namespace PhaseField
{
  /** Boundary conditions built into the scalar Q1 space of all fields. */
  enum class BoundaryConditions
  {
    /** No constraints but hanging nodes (natural conditions). */
    natural,
    /** Homogeneous Dirichlet conditions on the whole boundary. */
    dirichlet,
    /** Periodic in every direction of the unit cell. */
    periodic
  };

  /**
   * The discretisation that every program of this library works on: a
   * distributed quad/hex mesh of [0,1]^dim (p4est), one scalar Q1 space
   * shared by all fields of a scheme, its constraints, the lumped mass and
   * stiffness matrices (LumpedOperators), narrow-band re-meshing around
   * the diffuse interface with the transfer of any number of fields, and
   * VTU/PVTU output with a .pvd time series.
   *
   * The fields of a scheme ((U, V, P) or (U, F)) are the blocks of a
   * Trilinos block vector whose blocks all live in this one space
   * (reinit()). Block 0 is always the phase field U, which steers the
   * narrow band.
   */
  template <int dim>
  class Discretization
  {
  public:
    /** What the discretisation is built from. */
    struct Settings
    {
      /** Levels, narrow band width, stiffness quadrature. */
      MeshParameters mesh;
      /**
       * Hysteresis of the narrow band: cells are coarsened only outside
       * this many times `Mesh / Band width` (1: coarsen everything outside
       * the refinement band). Coarsening where 1 - |U| is not negligible
       * changes the discrete energy at every re-meshing.
       */
      double             coarsening_band_factor = 1;
      BoundaryConditions boundary_conditions    = BoundaryConditions::natural;
      /**
       * The solver and operator backend of the run
       * (resolve_solver_choice()): the mesh builds L with the backend
       * (LumpedOperators) and keeps its levels if the backend needs them
       * (OperatorBackendEntry::multigrid_levels; not with periodic
       * conditions).
       */
      SolverChoice solver;
    };

    Discretization(const Settings &settings, const MPI_Comm mpi_communicator);

    /**
     * Create the mesh of [0,1]^dim and set up the DoFs: uniform at the
     * finest level if `Mesh / Adaptive` is false or @p signed_distance is
     * null; otherwise at the coarsest level with every cell within
     * `Band width` * @p epsilon of the zero level set of
     * @p signed_distance on the finest level.
     */
    void
    create_mesh(const dealii::Function<dim> *signed_distance,
                const double                 epsilon);

    /**
     * Adapt the narrow band to the phase field in block 0 of @p fields
     * and transfer all blocks to the new mesh (interpolation; the
     * constraints are not yet distributed). Returns false, leaving mesh
     * and fields alone, if no cell is to be refined or coarsened. With
     * @p use_margin, also if the mesh fits the band within `Mesh / Band
     * margin`: the band narrowed by it is on the finest level, and no
     * group of finest sibling cells lies outside the coarsening band
     * widened by it;
     * otherwise adapts until the whole band is on the finest level.
     * @p band_scale multiplies `Mesh / Band width`, the coarsening band and
     * the margin for this adaptation. Collective.
     */
    bool
    adapt_to_phase_field(BlockVector &fields,
                         const double band_scale = 1,
                         const bool   use_margin = false);

    /**
     * adapt_to_phase_field() for the phase field in block 0 of the first
     * of @p fields, transferring all blocks of all of them.
     */
    bool
    adapt_to_phase_field(const std::vector<BlockVector *> &fields,
                         const double                      band_scale,
                         const bool                        use_margin);

    /**
     * Whether the band of the phase field in block 0 of @p fields,
     * narrowed by `Mesh / Band margin`, lies on the finest level: whether
     * the current mesh resolves @p fields as a re-meshing would leave it
     * (the coarsening side is not checked). Collective.
     */
    bool
    resolves_band(const BlockVector &fields) const;

    /**
     * Refine, never coarsen, until the band of the phase field in block 0
     * of the first of @p fields is on the finest level, transferring all
     * blocks of all @p fields (constraints not yet distributed). The band
     * of any earlier field on the mesh is kept: the mesh after a time step
     * whose interface left the band, on which the step is repeated.
     * Returns whether the mesh changed. Collective.
     */
    bool
    refine_to_band(const std::vector<BlockVector *> &fields);

    /**
     * Before create_mesh(): make @p level, at most the finest level of the
     * settings, the finest level of the mesh to be created. refine_to_level()
     * raises it later (a computation that starts on coarser meshes).
     */
    void
    start_at_level(const unsigned int level);

    /**
     * Make @p level (not below the current one) the finest level of the
     * narrow band and refine the band of the phase field in block 0 of
     * @p fields to it, transferring all blocks (constraints not yet
     * distributed): the transition to a finer level of a multilevel
     * schedule. @p band_scale multiplies the band width as in
     * adapt_to_phase_field(): a phase field that will be sharpened to a
     * profile of epsilon * band_scale after the transfer needs a band
     * only band_scale times as wide. Collective.
     */
    void
    refine_to_level(const unsigned int level,
                    BlockVector       &fields,
                    const double       band_scale = 1);

    /**
     * Write the mesh and all blocks of @p fields to the files
     * @p filename_base, @p filename_base_fixed.data and
     * @p filename_base.info (parallel::distributed::Triangulation::save()
     * with a SolutionTransfer). The directory must exist. Collective.
     */
    void
    save(const std::string &filename_base, const BlockVector &fields) const;

    /**
     * Read what save() wrote, on any number of MPI ranks: create the coarse
     * mesh as create_mesh() does, load the refinement, set up the DoFs and
     * read the fields into @p fields, which must have as many blocks as
     * were saved (their sizes do not matter; constraints are not
     * distributed). Replaces any current mesh: the cells (and DoFs) are
     * then in the order of p4est, whatever the history of the saved mesh.
     * Collective.
     */
    void
    load(const std::string &filename_base, BlockVector &fields);

    /** Time and file of every output written so far (the .pvd records). */
    const std::vector<std::pair<double, std::string>> &
    get_pvd_records() const
    {
      return pvd_records;
    }

    /**
     * Replace the .pvd records (a resumed run continues the .pvd of the
     * run it resumes); the next write_output() appends to them.
     */
    void
    set_pvd_records(const std::vector<std::pair<double, std::string>> &records)
    {
      pvd_records = records;
    }

    /** @p v = @p n_fields blocks in the Q1 space, locally owned, zero. */
    void
    reinit(BlockVector &v, const unsigned int n_fields) const;

    /** Apply the constraints (hanging nodes, boundary) to every block. */
    void
    distribute_constraints(BlockVector &v) const;

    /** Nodal interpolation of @p function into @p v. */
    void
    interpolate(const dealii::Function<dim> &function, Vector &v) const;

    /**
     * ||@p u - @p exact|| in the norm @p norm (L2 or H1), by Gauss
     * quadrature with 3 points per direction; @p u must satisfy the
     * constraints.
     */
    double
    error(const Vector                       &u,
          const dealii::Function<dim>        &exact,
          const dealii::VectorTools::NormType norm) const;

    /**
     * Write the named @p fields with the MPI subdomain and refinement
     * level of every cell as solution_<step>.pvtu into @p directory and
     * add them to solution.pvd there (with the time @p time).
     */
    void
    write_output(
      const std::string                                         &directory,
      const unsigned int                                         step,
      const double                                               time,
      const std::vector<std::pair<std::string, const Vector *>> &fields);

    const dealii::parallel::distributed::Triangulation<dim> &
    get_triangulation() const
    {
      return triangulation;
    }
    const dealii::DoFHandler<dim> &
    get_dof_handler() const
    {
      return dof_handler;
    }
    const dealii::AffineConstraints<double> &
    get_constraints() const
    {
      return constraints;
    }
    const LumpedOperators<dim> &
    get_operators() const
    {
      return operators;
    }
    MPI_Comm
    get_mpi_communicator() const
    {
      return mpi_communicator;
    }
    const Settings &
    get_settings() const
    {
      return settings;
    }

    /**
     * Throw an InputError naming @p user (a scheme) unless the stiffness
     * operator is assembled (OperatorBackendEntry::assembled_matrix of
     * the backend of Settings::solver): for what multiplies or factorises
     * the matrix itself. Can be called before create_mesh().
     */
    void
    require_assembled_operators(const std::string &user) const;

    /** Number of DoFs of one field. */
    dealii::types::global_dof_index
    n_dofs() const
    {
      return dof_handler.n_dofs();
    }

    /** A copy of @p v with the ghost entries of the locally relevant DoFs. */
    Vector
    ghosted_copy(const Vector &v) const;

    /**
     * How evenly the current mesh is spread over the ranks: the fewest
     * and most locally owned active cells and DoFs (of one field) of any
     * rank. p4est gives every rank the same number of cells up to one; the
     * DoFs on the partition boundaries belong to the lower rank.
     */
    struct PartitionBalance
    {
      unsigned int                     n_ranks;
      dealii::types::global_cell_index min_cells, max_cells;
      dealii::types::global_dof_index  min_dofs, max_dofs;
    };

    /** The spread of the current mesh over the ranks. Collective. */
    PartitionBalance
    partition_balance() const;

    /**
     * Print in one line on @p pcout the memory of the mesh
     * (triangulation), the DoF handler, the constraints, the lumped mass
     * and L (stiffness_operator()), summed over the ranks. Collective.
     */
    void
    print_memory_by_item(const dealii::ConditionalOStream &pcout) const;

    /**
     * Print partition_balance() in one line on @p pcout, with the largest
     * share of a rank relative to the mean. Collective.
     */
    void
    print_partition_balance(const dealii::ConditionalOStream &pcout) const;

  private:
    /**
     * The coarse mesh: one cell [0,1]^dim, boundary ids 2d (x_d = 0) and
     * 2d+1 (x_d = 1), periodic faces matched if the conditions are.
     */
    void
    create_coarse_mesh();

    /**
     * One adaptation of the band of @p band_width (in units of epsilon) to
     * the phase field in block 0 of the first of @p fields, as
     * adapt_to_phase_field() without the margin, coarsening down to
     * @p coarsest_level (the finest level: refinement only); all blocks
     * of all @p fields are transferred. False if no flag is left after
     * smoothing.
     */
    bool
    adapt_band_once(const std::vector<BlockVector *> &fields,
                    const double                      band_width,
                    const unsigned int                coarsest_level);

    /** @p fields with the ghost entries the transfer reads. */
    std::vector<Vector>
    ghosted_copies(const BlockVector &fields) const;

    /**
     * Execute the flagged refinement and coarsening, set up the DoFs and
     * interpolate the @p ghosted copies of @p fields to the new mesh.
     */
    void
    execute_with_transfer(const std::vector<Vector> &ghosted,
                          BlockVector               &fields);

    /**
     * execute_with_transfer() for several block vectors: @p ghosted holds
     * the copies of all blocks of all @p fields, in order.
     */
    void
    execute_with_transfer(const std::vector<Vector>        &ghosted,
                          const std::vector<BlockVector *> &fields);

    /**
     * Gauss points per direction beyond the degree of the elements in
     * error(): exact for the Q1 part, 3 points per direction for the
     * exact solution.
     */
    static constexpr unsigned int error_quadrature_extra_points = 2;

    /**
     * The L2 norm of @p ghosted - @p exact, integrated cell by cell in
     * double precision with the rule of error(). VectorTools::
     * integrate_difference() allocates its scratch vectors for every cell
     * and sums in single precision: callgrind, 10 quarter-circle steps at
     * h = 2^-9, 1 rank, 11 calls: 2.72e9 -> 0.75e9 instructions, a third
     * of them in tanh() of the exact solution.
     */
    double
    l2_error(const Vector &ghosted, const dealii::Function<dim> &exact) const;

    /** DoFs, constraints and lumped operators on the current mesh. */
    void
    setup_dofs();

    Settings settings;
    MPI_Comm mpi_communicator;

    dealii::parallel::distributed::Triangulation<dim> triangulation;
    dealii::FE_Q<dim>                                 fe;
    dealii::DoFHandler<dim>                           dof_handler;
    dealii::AffineConstraints<double>                 constraints;
    LumpedOperators<dim>                              operators;

    /** Time and file of every output written so far (for the .pvd). */
    std::vector<std::pair<double, std::string>> pvd_records;
  };
} // namespace PhaseField

#endif
