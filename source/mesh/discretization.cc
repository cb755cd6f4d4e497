#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_cartesian.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <phasefield/core/file_io.h>
#include <phasefield/core/statistics.h>
#include <phasefield/mesh/discretization.h>
#include <phasefield/mesh/narrow_band.h>
#include <phasefield/mesh/operator_backend.h>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    /**
     * Write the VTU file of each rank and, on rank 0, the PVTU record of
     * @p step and solution.pvd with @p pvd_records plus this step's
     * record (the files of DataOut::write_vtu_with_pvtu_record()), each
     * write checked on every rank (file_io.h). Collective.
     */
    template <int dim>
    void
    write_vtu_files(const DataOut<dim>                          &data_out,
                    const std::string                           &directory,
                    const unsigned int                           step,
                    const double                                 time,
                    std::vector<std::pair<double, std::string>> &pvd_records,
                    const MPI_Comm mpi_communicator)
    {
      constexpr unsigned int n_digits = 5;
      const std::string      stem =
        "solution_" + Utilities::int_to_string(step, n_digits);
      const auto piece = [&](const unsigned int rank) {
        return stem + "." + std::to_string(rank) + ".vtu";
      };
      run_on_every_rank(mpi_communicator, [&]() {
        write_checked(directory + "/" +
                        piece(
                          Utilities::MPI::this_mpi_process(mpi_communicator)),
                      [&](std::ostream &out) { data_out.write_vtu(out); });
      });
      std::vector<std::string> pieces;
      for (unsigned int rank = 0;
           rank < Utilities::MPI::n_mpi_processes(mpi_communicator);
           ++rank)
        pieces.push_back(piece(rank));
      const std::string pvtu = stem + ".pvtu";
      pvd_records.emplace_back(time, pvtu);
      run_on_root(mpi_communicator, [&]() {
        write_checked(directory + "/" + pvtu, [&](std::ostream &out) {
          data_out.write_pvtu_record(out, pieces);
        });
        // a complete new record or the old one: written, then renamed
        const std::string pvd = directory + "/solution.pvd";
        write_checked(pvd + ".tmp", [&](std::ostream &out) {
          DataOutBase::write_pvd_record(out, pvd_records);
        });
        std::filesystem::rename(pvd + ".tmp", pvd);
      });
    }



    /**
     * deal.II's smoothing on coarsening and the 2:1 balance at vertices,
     * without eliminate_unrefined_islands (refine a coarse cell surrounded
     * by finer ones). On a parallel::distributed::Triangulation that
     * smoothing sees only the cells of its own rank and ghosts: the level-7
     * quarter circle had 3127 cells on 1 and 2 ranks and 3124 on 4. Without
     * it, the meshes are the same on 1, 2 and 4 ranks. With narrow-band
     * coarsening it could also undo the coarsening of the previous
     * re-meshing, so that a stationary interface made the mesh alternate.
     */
    template <int dim>
    typename Triangulation<dim>::MeshSmoothing
    mesh_smoothing()
    {
      using Tria = Triangulation<dim>;
      return
        typename Tria::MeshSmoothing(Tria::limit_level_difference_at_vertices |
                                     Tria::smoothing_on_coarsening);
    }



    /** Number of cells flagged for refinement or coarsening on all ranks. */
    template <int dim>
    unsigned int
    n_flagged_cells(const parallel::distributed::Triangulation<dim> &tria)
    {
      unsigned int n_flagged = 0;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned() &&
            (cell->refine_flag_set() || cell->coarsen_flag_set()))
          ++n_flagged;
      return Utilities::MPI::sum(n_flagged, tria.get_communicator());
    }
  } // namespace



  template <int dim>
  Discretization<dim>::Discretization(const Settings &settings,
                                      const MPI_Comm  mpi_communicator)
    : settings(settings)
    , mpi_communicator(mpi_communicator)
    , triangulation(
        mpi_communicator,
        mesh_smoothing<dim>(),
        operator_backend(settings.solver.backend).multigrid_levels ?
          parallel::distributed::Triangulation<
            dim>::construct_multigrid_hierarchy :
          parallel::distributed::Triangulation<dim>::default_setting)
    , fe(1)
    , dof_handler(triangulation)
  {
    if (operator_backend(settings.solver.backend).multigrid_levels &&
        settings.boundary_conditions == BoundaryConditions::periodic)
      throw InputError("<Linear solver / Type> = " + settings.solver.backend +
                       " does not support periodic boundary conditions: use "
                       "iterative or direct.");
  }



  template <int dim>
  void
  Discretization<dim>::require_assembled_operators(
    const std::string &user) const
  {
    if (!operator_backend(settings.solver.backend).assembled_matrix)
      throw InputError(user +
                       " needs the assembled stiffness matrix, which "
                       "<Linear solver / Type> = " +
                       settings.solver.backend +
                       " does not store: use <Linear solver / Type> = "
                       "iterative or direct, or the nested scheme.");
  }



  template <int dim>
  void
  Discretization<dim>::create_coarse_mesh()
  {
    const bool periodic =
      settings.boundary_conditions == BoundaryConditions::periodic;
    // colorize: boundary id 2d (x_d = 0) and 2d+1 (x_d = 1)
    GridGenerator::hyper_cube(triangulation, 0., 1., periodic);
    if (periodic)
      {
        std::vector<GridTools::PeriodicFacePair<
          typename parallel::distributed::Triangulation<dim>::cell_iterator>>
          periodicity_vector;
        for (unsigned int d = 0; d < dim; ++d)
          GridTools::collect_periodic_faces(
            triangulation, 2 * d, 2 * d + 1, d, periodicity_vector);
        triangulation.add_periodicity(periodicity_vector);
      }
  }



  template <int dim>
  void
  Discretization<dim>::create_mesh(const Function<dim> *signed_distance,
                                   const double         epsilon)
  {
    const MeshParameters &mesh = settings.mesh;
    create_coarse_mesh();
    if (!mesh.adaptive || signed_distance == nullptr)
      triangulation.refine_global(mesh.finest_level);
    else
      {
        triangulation.refine_global(mesh.coarsest_level);
        NarrowBand::refine_around_zero_level_set(triangulation,
                                                 *signed_distance,
                                                 mesh.band_width,
                                                 epsilon,
                                                 mesh.finest_level);
      }
    setup_dofs();
  }



  template <int dim>
  void
  Discretization<dim>::setup_dofs()
  {
    dof_handler.distribute_dofs(fe);
    if (operator_backend(settings.solver.backend).multigrid_levels)
      dof_handler.distribute_mg_dofs();

    IndexSet locally_relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant);
    constraints.clear();
    constraints.reinit(locally_relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    switch (settings.boundary_conditions)
      {
        case BoundaryConditions::dirichlet:
          VectorTools::interpolate_boundary_values(
            dof_handler, 0, Functions::ZeroFunction<dim>(), constraints);
          break;
        case BoundaryConditions::periodic:
          for (unsigned int d = 0; d < dim; ++d)
            DoFTools::make_periodicity_constraints(
              dof_handler, 2 * d, 2 * d + 1, d, constraints);
          break;
        case BoundaryConditions::natural:
          break;
      }
    constraints.close();

    typename LumpedOperators<dim>::Settings operator_settings;
    operator_settings.stiffness_quadrature = settings.mesh.stiffness_quadrature;
    operator_settings.backend              = settings.solver.backend;
    operator_settings.dirichlet =
      settings.boundary_conditions == BoundaryConditions::dirichlet;
    operators.reinit(dof_handler,
                     constraints,
                     mpi_communicator,
                     operator_settings);
  }



  template <int dim>
  std::vector<Vector>
  Discretization<dim>::ghosted_copies(const BlockVector &fields) const
  {
    std::vector<Vector> ghosted;
    for (unsigned int b = 0; b < fields.n_blocks(); ++b)
      ghosted.push_back(ghosted_copy(fields.block(b)));
    return ghosted;
  }



  template <int dim>
  Vector
  Discretization<dim>::ghosted_copy(const Vector &v) const
  {
    Vector ghosted(operators.locally_owned_dofs,
                   operators.locally_relevant_dofs,
                   mpi_communicator);
    ghosted = v;
    return ghosted;
  }



  template <int dim>
  typename Discretization<dim>::PartitionBalance
  Discretization<dim>::partition_balance() const
  {
    const auto cells = Utilities::MPI::min_max_avg(
      double(triangulation.n_locally_owned_active_cells()), mpi_communicator);
    const auto dofs =
      Utilities::MPI::min_max_avg(double(dof_handler.n_locally_owned_dofs()),
                                  mpi_communicator);
    return {Utilities::MPI::n_mpi_processes(mpi_communicator),
            types::global_cell_index(cells.min),
            types::global_cell_index(cells.max),
            types::global_dof_index(dofs.min),
            types::global_dof_index(dofs.max)};
  }



  template <int dim>
  void
  Discretization<dim>::print_memory_by_item(
    const ConditionalOStream &pcout) const
  {
    constexpr double bytes_per_mib = 1024. * 1024.;
    const auto       mib           = [this](const std::size_t bytes) {
      return Utilities::MPI::sum(static_cast<double>(bytes), mpi_communicator) /
             bytes_per_mib;
    };
    const double mesh        = mib(triangulation.memory_consumption());
    const double dofs        = mib(dof_handler.memory_consumption());
    const double constrained = mib(constraints.memory_consumption());
    const double mass        = mib(operators.lumped_mass.memory_consumption() +
                            operators.inverse_lumped_mass.memory_consumption());
    const double stiffness =
      mib(operators.stiffness_operator().memory_consumption());
    pcout << "Memory by item, summed over the ranks (MiB): mesh " << std::fixed
          << std::setprecision(0) << mesh << ", DoF handler " << dofs
          << ", constraints " << constrained << ", lumped mass " << mass
          << ", stiffness operator " << stiffness << " (" << n_dofs()
          << " DoFs per field)" << std::defaultfloat << std::endl;
  }



  template <int dim>
  void
  Discretization<dim>::print_partition_balance(
    const ConditionalOStream &pcout) const
  {
    const PartitionBalance balance = partition_balance();
    const double mean_dofs = double(dof_handler.n_dofs()) / balance.n_ranks;
    pcout << "Partition of the final mesh over " << balance.n_ranks
          << " rank(s): " << balance.min_cells << "-" << balance.max_cells
          << " cells and " << balance.min_dofs << "-" << balance.max_dofs
          << " DoFs per field per rank (largest share " << std::fixed
          << std::setprecision(3) << balance.max_dofs / mean_dofs
          << " x the mean)" << std::defaultfloat << std::endl;
  }



  template <int dim>
  void
  Discretization<dim>::save(const std::string &filename_base,
                            const BlockVector &fields) const
  {
    const std::vector<Vector>   ghosted = ghosted_copies(fields);
    std::vector<const Vector *> in;
    for (const auto &g : ghosted)
      in.push_back(&g);
    // the transfer attaches the fields to the cells until save() has
    // written them
    parallel::distributed::SolutionTransfer<dim, Vector> transfer(dof_handler);
    transfer.prepare_for_serialization(in);
    triangulation.save(filename_base);
  }



  template <int dim>
  void
  Discretization<dim>::load(const std::string &filename_base,
                            BlockVector       &fields)
  {
    // the loaded mesh has its cells (and so its DoFs) in p4est's order,
    // which does not depend on the history of the mesh; the operators
    // of the old mesh are freed first, as in a re-meshing
    operators.release();
    triangulation.clear();
    create_coarse_mesh();
    triangulation.load(filename_base);
    setup_dofs();
    reinit(fields, fields.n_blocks());
    std::vector<Vector *> out;
    for (unsigned int b = 0; b < fields.n_blocks(); ++b)
      out.push_back(&fields.block(b));
    parallel::distributed::SolutionTransfer<dim, Vector> transfer(dof_handler);
    transfer.deserialize(out);
    // what the old mesh and the unpacking freed goes back to the system,
    // as after a re-meshing (doc/benchmarks.md, "Choices in the code")
    return_free_heap_memory();
  }



  template <int dim>
  bool
  Discretization<dim>::adapt_to_phase_field(BlockVector &fields,
                                            const double band_scale,
                                            const bool   use_margin)
  {
    return adapt_to_phase_field(std::vector<BlockVector *>{&fields},
                                band_scale,
                                use_margin);
  }



  template <int dim>
  bool
  Discretization<dim>::adapt_to_phase_field(
    const std::vector<BlockVector *> &fields,
    const double                      band_scale,
    const bool                        use_margin)
  {
    const MeshParameters &mesh       = settings.mesh;
    const double          band_width = band_scale * mesh.band_width;
    if (!use_margin || mesh.band_margin <= 0)
      return adapt_band_once(fields, band_width, mesh.coarsest_level);
    // finest cells are kept out to the coarsening band plus the margin
    const double margin      = band_scale * mesh.band_margin;
    const double outer_width = settings.coarsening_band_factor * band_width;
    const auto   fits        = [&](const double inner) {
      return NarrowBand::band_fits(dof_handler,
                                   ghosted_copy(fields[0]->block(0)),
                                   inner,
                                   outer_width + margin,
                                   mesh.finest_level);
    };
    if (fits(band_width - margin))
      return false;
    // one adaptation refines or coarsens a cell by one level: where the
    // interface moved into cells several levels coarser, repeat until the
    // whole band is on the finest level again
    bool changed = false;
    for (unsigned int level = mesh.coarsest_level;
         level < mesh.finest_level && !fits(band_width);
         ++level)
      {
        if (!adapt_band_once(fields, band_width, mesh.coarsest_level))
          break;
        changed = true;
      }
    return changed;
  }



  template <int dim>
  bool
  Discretization<dim>::adapt_band_once(const std::vector<BlockVector *> &fields,
                                       const double       band_width,
                                       const unsigned int coarsest_level)
  {
    const MeshParameters &mesh = settings.mesh;
    std::vector<Vector>   ghosted;
    for (const BlockVector *f : fields)
      for (Vector &g : ghosted_copies(*f))
        ghosted.push_back(std::move(g));
    NarrowBand::flag_cells_from_phase_field(dof_handler,
                                            ghosted[0],
                                            band_width,
                                            mesh.finest_level,
                                            coarsest_level,
                                            settings.coarsening_band_factor *
                                              band_width);
    // smoothing removes flags that cannot be executed (2:1 balance,
    // incomplete sibling groups); keep the mesh if none is left
    triangulation.prepare_coarsening_and_refinement();
    if (n_flagged_cells(triangulation) == 0)
      return false;
    execute_with_transfer(ghosted, fields);
    return true;
  }



  template <int dim>
  bool
  Discretization<dim>::resolves_band(const BlockVector &fields) const
  {
    const MeshParameters &mesh = settings.mesh;
    return NarrowBand::band_fits(dof_handler,
                                 ghosted_copy(fields.block(0)),
                                 mesh.band_width - mesh.band_margin,
                                 std::numeric_limits<double>::infinity(),
                                 mesh.finest_level);
  }



  template <int dim>
  bool
  Discretization<dim>::refine_to_band(const std::vector<BlockVector *> &fields)
  {
    const MeshParameters &mesh    = settings.mesh;
    bool                  changed = false;
    // one adaptation refines a cell by one level; with the finest level
    // as the coarsest one no cell is coarsened
    for (unsigned int level = mesh.coarsest_level; level < mesh.finest_level;
         ++level)
      {
        if (!adapt_band_once(fields, mesh.band_width, mesh.finest_level))
          break;
        changed = true;
      }
    return changed;
  }



  template <int dim>
  void
  Discretization<dim>::execute_with_transfer(const std::vector<Vector> &ghosted,
                                             BlockVector               &fields)
  {
    execute_with_transfer(ghosted, std::vector<BlockVector *>{&fields});
  }



  template <int dim>
  void
  Discretization<dim>::execute_with_transfer(
    const std::vector<Vector>        &ghosted,
    const std::vector<BlockVector *> &fields)
  {
    {
      parallel::distributed::SolutionTransfer<dim, Vector> transfer(
        dof_handler);
      std::vector<const Vector *> in;
      for (const auto &g : ghosted)
        in.push_back(&g);
      transfer.prepare_for_coarsening_and_refinement(in);
      // the operators of the old mesh are not needed any more: free them
      // before the refinement packs the fields, the peak of a re-meshing,
      // and return the pages the solver left free to the system
      // (doc/benchmarks.md, "Choices in the code")
      operators.release();
      return_free_heap_memory();
      triangulation.execute_coarsening_and_refinement();

      setup_dofs();
      std::vector<Vector *> out;
      for (BlockVector *f : fields)
        {
          reinit(*f, f->n_blocks());
          for (unsigned int b = 0; b < f->n_blocks(); ++b)
            out.push_back(&f->block(b));
        }
      transfer.interpolate(out);
    }
    return_free_heap_memory();
  }



  template <int dim>
  void
  Discretization<dim>::start_at_level(const unsigned int level)
  {
    AssertThrow(triangulation.n_levels() == 0,
                ExcMessage("start_at_level() comes before create_mesh()."));
    AssertThrow(level <= settings.mesh.finest_level &&
                  level >= settings.mesh.coarsest_level,
                ExcMessage("start_at_level() needs a level between the "
                           "coarsest and the finest level."));
    settings.mesh.finest_level = level;
  }



  template <int dim>
  void
  Discretization<dim>::refine_to_level(const unsigned int level,
                                       BlockVector       &fields,
                                       const double       band_scale)
  {
    AssertThrow(level >= settings.mesh.finest_level,
                ExcMessage("refine_to_level() cannot coarsen the band."));
    const unsigned int n_new   = level - settings.mesh.finest_level;
    settings.mesh.finest_level = level;
    // every adaptation refines the band (or the uniform mesh) by one level
    for (unsigned int i = 0; i < n_new; ++i)
      if (settings.mesh.adaptive)
        adapt_to_phase_field(fields, band_scale);
      else
        {
          const std::vector<Vector> ghosted = ghosted_copies(fields);
          for (const auto &cell : triangulation.active_cell_iterators())
            if (cell->is_locally_owned())
              cell->set_refine_flag();
          execute_with_transfer(ghosted, fields);
        }
  }



  template <int dim>
  void
  Discretization<dim>::reinit(BlockVector &v, const unsigned int n_fields) const
  {
    v.reinit(std::vector<IndexSet>(n_fields, operators.locally_owned_dofs),
             mpi_communicator);
  }



  template <int dim>
  void
  Discretization<dim>::distribute_constraints(BlockVector &v) const
  {
    for (unsigned int b = 0; b < v.n_blocks(); ++b)
      constraints.distribute(v.block(b));
  }



  template <int dim>
  void
  Discretization<dim>::interpolate(const Function<dim> &function,
                                   Vector              &v) const
  {
    VectorTools::interpolate(dof_handler, function, v);
  }



  template <int dim>
  double
  Discretization<dim>::error(const Vector               &u,
                             const Function<dim>        &exact,
                             const VectorTools::NormType norm) const
  {
    Vector ghosted(operators.locally_owned_dofs,
                   operators.locally_relevant_dofs,
                   mpi_communicator);
    ghosted = u;
    if (norm == VectorTools::L2_norm)
      return l2_error(ghosted, exact);
    const QGauss<dim>     quadrature(fe.degree + error_quadrature_extra_points);
    dealii::Vector<float> cellwise(triangulation.n_active_cells());
    // the cells are axis-parallel boxes (refined [0,1]^d): the Cartesian
    // mapping gives the points and weights of the default MappingQ1 up to
    // round-off, for less (callgrind, 10 quarter-circle steps at
    // h = 2^-9: l2_error 2.90e9 -> 2.72e9 instructions)
    const MappingCartesian<dim> mapping;
    VectorTools::integrate_difference(
      mapping, dof_handler, ghosted, exact, cellwise, quadrature, norm);
    return VectorTools::compute_global_error(triangulation, cellwise, norm);
  }



  template <int dim>
  double
  Discretization<dim>::l2_error(const Vector        &ghosted,
                                const Function<dim> &exact) const
  {
    const QGauss<dim> quadrature(fe.degree + error_quadrature_extra_points);
    const MappingCartesian<dim> mapping;
    FEValues<dim>               fe_values(mapping,
                            fe,
                            quadrature,
                            update_values | update_quadrature_points |
                              update_JxW_values);
    // FEValues::get_function_values() allocates a vector per cell: the
    // values at the quadrature points are summed here from the DoF values
    std::vector<double> dof_values(fe.n_dofs_per_cell());
    std::vector<double> exact_values(quadrature.size());
    double              sum = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          cell->get_dof_values(ghosted, dof_values.begin(), dof_values.end());
          exact.value_list(fe_values.get_quadrature_points(), exact_values);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              double difference = -exact_values[q];
              for (unsigned int i = 0; i < dof_values.size(); ++i)
                difference += dof_values[i] * fe_values.shape_value(i, q);
              sum += difference * difference * fe_values.JxW(q);
            }
        }
    return std::sqrt(Utilities::MPI::sum(sum, mpi_communicator));
  }



  template <int dim>
  void
  Discretization<dim>::write_output(
    const std::string                                         &directory,
    const unsigned int                                         step,
    const double                                               time,
    const std::vector<std::pair<std::string, const Vector *>> &fields)
  {
    std::vector<Vector> ghosted(fields.size());
    DataOut<dim>        data_out;
    data_out.attach_dof_handler(dof_handler);
    for (unsigned int i = 0; i < fields.size(); ++i)
      {
        ghosted[i].reinit(operators.locally_owned_dofs,
                          operators.locally_relevant_dofs,
                          mpi_communicator);
        ghosted[i] = *fields[i].second;
        data_out.add_data_vector(ghosted[i], fields[i].first);
      }
    dealii::Vector<float> subdomain(triangulation.n_active_cells());
    dealii::Vector<float> level(triangulation.n_active_cells());
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          subdomain(cell->active_cell_index()) = cell->subdomain_id();
          level(cell->active_cell_index())     = cell->level();
        }
    data_out.add_data_vector(subdomain, "subdomain");
    data_out.add_data_vector(level, "level");
    data_out.build_patches();
    DataOutBase::VtkFlags flags;
    flags.time  = time;
    flags.cycle = step;
    // zlib's fastest level: with deal.II's default (best compression),
    // deflate was most of the output's instructions (callgrind, 10
    // quarter-circle steps at h = 2^-9, 2 VTU files of 22,750 cells:
    // output 8.71e9 -> 1.36e9 instructions)
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);
    write_vtu_files(
      data_out, directory, step, time, pvd_records, mpi_communicator);
  }



  template class Discretization<2>;
  template class Discretization<3>;
} // namespace PhaseField
