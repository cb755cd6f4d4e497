#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <phasefield/core/constants.h>
#include <phasefield/core/statistics.h>
#include <phasefield/geometry/shapes.h>
#include <phasefield/problems/contour_output.h>
#include <phasefield/problems/contour_problem.h>
#include <phasefield/problems/initial_shape_check.h>
#include <phasefield/time/checkpoint.h>
#include <sstream>
#include <stdexcept>

namespace PhaseField
{
  using namespace dealii;

  namespace
  {
    /** The setup of the contour problem for PhaseFieldProblem. */
    template <int dim>
    typename PhaseFieldProblem<dim>::Setup
    contour_setup(const ContourParameters &parameters)
    {
      typename PhaseFieldProblem<dim>::Setup setup;
      setup.program_name = "shape_from_contour";
      setup.signed_distance =
        Shapes::create_signed_distance<dim>(parameters.willmore.geometry);
      setup.outer_energy.willmore_weight = parameters.model.willmore_weight;
      setup.outer_energy.area_weight     = parameters.model.area_weight;
      // the mesh is refined level by level up to the last one
      setup.finest_level = parameters.multilevel.levels.back();
      return setup;
    }

    /**
     * Throw an InputError if the target labeling @p alpha (on the pixel
     * grid of @p level) is below smallest_target_label everywhere: an
     * empty target (a shape outside the domain or covering it, or an image
     * of zeros) has no contour, and the flow towards it only destroys the
     * shape.
     */
    void
    check_target_not_empty(const std::vector<double> &alpha,
                           const TargetParameters    &target,
                           const unsigned int         level)
    {
      constexpr double smallest_target_label = 1e-3;
      double           largest               = 0;
      for (const double value : alpha)
        largest = std::max(largest, std::abs(value));
      if (largest >= smallest_target_label)
        return;
      const std::string check =
        target.is_image() ?
          "Check <Target / Image file> (not all black) and <Target / Maximum "
          "label> (positive)." :
          "The target shape (<Target / Shape> = " + target.shape.shape +
            ") must cross the domain [0,1]^d, neither outside it nor "
            "covering it: check <Target / Center>, <Radius>, <Sizes> or "
            "<Expression>.";
      throw InputError("The target labeling alpha* is below " +
                       std::to_string(smallest_target_label) +
                       " at every point of the pixel grid of level " +
                       std::to_string(level) +
                       ": the target has no contour to fit. " + check);
    }
  } // namespace



  template <int dim>
  ContourProblem<dim>::ContourProblem(const ContourParameters &parameters)
    : PhaseFieldProblem<dim>(parameters.willmore,
                             contour_setup<dim>(parameters))
    , parameters(parameters)
  {
    if (parameters.target.is_image())
      target_image = Images::read_gray_image(parameters.target.image_file,
                                             "Target / Image file");
  }



  template <int dim>
  void
  ContourProblem<dim>::set_first_level()
  {
    first_level_index =
      this->willmore_parameters.checkpoint.resume ? resumed_level_index() : 0;
    this->level_parameters = parameters.for_level(first_level_index);
  }



  template <int dim>
  void
  ContourProblem<dim>::print_header() const
  {
    PhaseFieldProblem<dim>::print_header();
    this->pcout << "levels";
    for (const unsigned int level : parameters.multilevel.levels)
      this->pcout << ' ' << level;
    this->pcout << ", mu = " << parameters.model.willmore_weight
                << ", eta = " << parameters.model.area_weight
                << ", gamma = " << parameters.model.mismatch_weight << ", "
                << (parameters.time_stepping.coupling ==
                        ContourCoupling::monolithic ?
                      "monolithic coupling" :
                      "split coupling (Algorithm 6.1)")
                << (parameters.time_stepping.step_size_control ?
                      ", step size control" :
                      "")
                << std::endl;
  }



  template <int dim>
  OuterEnergy
  ContourProblem<dim>::scheme_outer_energy() const
  {
    OuterEnergy outer = this->setup.outer_energy;
    if (parameters.time_stepping.coupling == ContourCoupling::monolithic)
      outer.data_term = &level_mismatch;
    return outer;
  }



  template <int dim>
  void
  ContourProblem<dim>::run_time_loops()
  {
    unsigned int step = 0;
    double       time = 0;
    for (unsigned int i = first_level_index;
         i < parameters.multilevel.levels.size();
         ++i)
      {
        if (i > first_level_index)
          move_to_level(i);
        start_level(i);
        typename TimeLoop<dim>::Settings settings =
          this->time_loop_settings(this->level_parameters);
        // a level whose steps are done continues with the next one; a
        // resume after the last level's steps is refused, as in the
        // other programs
        settings.refuse_empty_resume =
          i + 1 == parameters.multilevel.levels.size();
        if (parameters.time_stepping.step_size_control)
          settings.largest_step_factor =
            parameters.time_stepping.largest_tau_factor;
        TimeLoop<dim> time_loop(settings,
                                this->discretization,
                                *this->scheme,
                                *this,
                                this->pcout,
                                this->computing_timer);
        run_level(time_loop, i, step, time);
        step = time_loop.get_last_step();
        time = time_loop.get_time();
        write_level_results(i + 1 == parameters.multilevel.levels.size());
      }
  }



  template <int dim>
  void
  ContourProblem<dim>::run_level(TimeLoop<dim>     &time_loop,
                                 const unsigned int index,
                                 const unsigned int step,
                                 const double       time)
  {
    try
      {
        if (this->willmore_parameters.checkpoint.resume &&
            index == first_level_index)
          time_loop.resume(this->solution);
        else if (index == 0)
          time_loop.run(this->solution);
        else
          time_loop.continue_run(this->solution, step, time);
      }
    catch (const ExceptionBase &exc)
      {
        // a step failed (after all halvings, or by an error of a solver)
        // only if its last attempt did not finish; other errors pass
        // unchanged
        if (!unfinished_sub_step)
          throw;
        std::ostringstream message;
        exc.print_info(message);
        throw std::runtime_error(
          step_failure_message(time_loop.get_last_step() + 1, message.str()));
      }
  }



  template <int dim>
  std::string
  ContourProblem<dim>::step_failure_message(const unsigned int step,
                                            const std::string &reason) const
  {
    const auto &[sub_step, tau] = *unfinished_sub_step;
    std::ostringstream text;
    text << "Step " << step << " of shape_from_contour (level "
         << this->level_parameters.mesh.finest_level << ") failed in ";
    switch (sub_step)
      {
        case SubStep::first_nested_step:
          text << "sub-step 1 of 3 of Algorithm 6.1, the nested step of the "
                  "regularisation with tau/2 = "
               << tau / 2
               << ", did not converge. Try a smaller <Time "
                  "stepping / Tau> or <Time stepping / Inner tau>, or larger "
                  "<Newton / Maximum iterations> or <Newton / Maximum step "
                  "halvings>.";
          break;
        case SubStep::mismatch_step:
          text << "sub-step 2 of 3 of Algorithm 6.1, the explicit mismatch "
                  "step with tau = "
               << tau
               << ", made the phase field not finite (nan or inf). The "
                  "step moves U by tau/epsilon times the mismatch gradient, "
                  "which is proportional to gamma: try a smaller <Model / "
                  "Mismatch weight> or <Time stepping / Tau>.";
          break;
        case SubStep::second_nested_step:
          text << "sub-step 3 of 3 of Algorithm 6.1, the nested step with "
                  "tau/2 = "
               << tau / 2
               << " from the result of the explicit mismatch step, did not "
                  "converge. The mismatch step moves U by "
                  "tau/epsilon times the mismatch gradient, which is "
                  "proportional to gamma, and may move it too far for "
                  "Newton's method: try a smaller <Model / Mismatch weight> "
                  "or <Time stepping / Tau>, or larger <Newton / Maximum "
                  "step halvings>.";
          break;
        case SubStep::monolithic_step:
          text << "the monolithic step (nested step with the mismatch in its "
                  "energy, <Time stepping / Contour coupling> = monolithic) "
                  "with tau = "
               << tau
               << " did not converge or broke the energy law of its whole "
                  "energy. Try a smaller <Time stepping / Tau> or <Model / "
                  "Mismatch weight>, or larger <Newton / Maximum step "
                  "halvings> or <Newton / Maximum descent iterations>.";
          break;
      }
    // without deal.II's indentation
    const std::size_t begin = reason.find_first_not_of(" \n");
    const std::size_t end   = reason.find_last_not_of(" \n");
    if (begin != std::string::npos)
      text << " (" << reason.substr(begin, end - begin + 1) << ")";
    return text.str();
  }



  template <int dim>
  unsigned int
  ContourProblem<dim>::resumed_level_index() const
  {
    const std::string path =
      Checkpoint::find_last(this->willmore_parameters.output_directory,
                            this->mpi_communicator);
    const std::vector<double> data =
      Checkpoint::read_state(path, this->mpi_communicator).problem_data;
    if (data.size() < n_level_entries)
      throw InputError("The checkpoint <" + path +
                       "> was not written by shape_from_contour (it has no "
                       "level): <Checkpoint / Resume> needs the output "
                       "directory of a shape_from_contour run.");
    const unsigned int               index = static_cast<unsigned int>(data[0]);
    const unsigned int               level = static_cast<unsigned int>(data[1]);
    const std::vector<unsigned int> &levels = parameters.multilevel.levels;
    if (index >= levels.size() || levels[index] != level)
      throw InputError("The checkpoint <" + path + "> was written on level " +
                       std::to_string(level) + ", entry " +
                       std::to_string(index + 1) +
                       " of <Multilevel / Levels>, which this run's "
                       "<Multilevel / Levels> does not have there: resume "
                       "with the levels of the run that wrote it.");
    return index;
  }



  template <int dim>
  Checkpoint::Parameters
  ContourProblem<dim>::own_checkpoint_parameters() const
  {
    const std::vector<unsigned int> &levels = parameters.multilevel.levels;
    const std::vector<double>        levels_so_far(levels.begin(),
                                            levels.begin() + level_index + 1);
    Checkpoint::Parameters           recorded = {
                {"Model / Willmore weight",
                 Checkpoint::exact_value(parameters.model.willmore_weight)},
                {"Model / Area weight",
                 Checkpoint::exact_value(parameters.model.area_weight)},
                {"Model / Mismatch weight",
                 Checkpoint::exact_value(parameters.model.mismatch_weight)},
                {"Multilevel / Levels", Checkpoint::exact_values(levels_so_far)},
                {"Time stepping / Contour coupling",
       parameters.time_stepping.coupling == ContourCoupling::monolithic ?
                   "monolithic" :
                   "split"},
                {"Time stepping / Step size control",
       parameters.time_stepping.step_size_control ? "true" : "false"}};
    if (parameters.target.is_image())
      {
        recorded.emplace_back("Target / Shape", "image");
        recorded.emplace_back("Target / Image file",
                              parameters.target.image_file);
        recorded.emplace_back("Target / Maximum label",
                              Checkpoint::exact_value(
                                parameters.target.maximum_label));
      }
    else
      for (const auto &entry :
           Checkpoint::geometry_parameters(parameters.target.shape))
        recorded.push_back(entry);
    return recorded;
  }



  template <int dim>
  std::vector<double>
  ContourProblem<dim>::checkpoint_data() const
  {
    std::vector<double> data{double(level_index),
                             double(this->level_parameters.mesh.finest_level)};
    data.insert(data.end(), criterion_history.begin(), criterion_history.end());
    // the step-size control's state last (checkpoints without it keep
    // their layout)
    if (parameters.time_stepping.step_size_control)
      data.push_back(tau_factor);
    return data;
  }



  template <int dim>
  void
  ContourProblem<dim>::after_load(BlockVector               &state,
                                  const std::vector<double> &problem_data)
  {
    (void)state;
    auto end = problem_data.end();
    if (parameters.time_stepping.step_size_control &&
        problem_data.size() > n_level_entries)
      tau_factor = *(--end);
    criterion_history.assign(problem_data.begin() + n_level_entries, end);
  }



  template <int dim>
  void
  ContourProblem<dim>::start_level(const unsigned int index)
  {
    TimerOutput::Scope t(this->computing_timer, "labeling: target");
    level_index               = index;
    this->level_parameters    = parameters.for_level(index);
    const unsigned int  level = this->level_parameters.mesh.finest_level;
    std::vector<double> target =
      target_on(HuffmanLabeling::LabelingGrid<dim>(level));
    check_target_not_empty(target, parameters.target, level);
    mismatch_term =
      std::make_unique<MismatchTerm<dim>>(this->discretization,
                                          level,
                                          std::move(target),
                                          parameters.model.mismatch_weight);
    criterion_history.clear();
    tau_factor = 1;
    this->pcout << "level " << this->level_parameters.mesh.finest_level
                << ": h = " << this->level_parameters.mesh.h()
                << ", epsilon = " << this->level_parameters.model.epsilon
                << ", tau = " << this->level_parameters.model.tau
                << ", inner tau = " << this->level_parameters.model.inner_tau
                << ", " << this->level_parameters.model.n_steps << " steps"
                << (parameters.multilevel.transition ==
                        LevelTransition::automatic ?
                      " at most" :
                      "")
                << std::endl;
    const std::string warning =
      epsilon_resolution_warning(this->level_parameters);
    if (!warning.empty())
      this->pcout << "Warning: " << warning << std::endl;
  }



  template <int dim>
  void
  ContourProblem<dim>::move_to_level(const unsigned int index)
  {
    const WillmoreParameters next = parameters.for_level(index);
    // the coarse level's term is on the coarse pixel grid, which the
    // refined cells do not fit: no data term until start_level() made the
    // next one (the initialisation below does not evaluate it)
    mismatch_term.reset();
    {
      TimerOutput::Scope t(this->computing_timer, "mesh: level transition");
      // U will be sharpened to the finer epsilon: |U_sharp| < tanh(b) iff
      // |U| < tanh(b eps_new / eps_old), so the band of the finer profile
      // is refined, not the wider one of the coarse epsilon
      const double ratio =
        this->level_parameters.model.epsilon / next.model.epsilon;
      this->refine_u_to_level(next.mesh.finest_level,
                              this->solution,
                              parameters.multilevel.sharpen ? 1 / ratio : 1);
      if (parameters.multilevel.sharpen)
        this->sharpen_profile(this->solution.block(0), ratio);
      this->discretization.distribute_constraints(this->solution);
    }
    TimerOutput::Scope t(this->computing_timer, "initialisation");
    this->create_scheme(next);
    // V and P are the inner minimiser and its multiplier for the coarse
    // epsilon and inner tau: solve them again for U (Algorithm 3.1)
    this->scheme->initialize(this->solution, next.model.tau);
  }



  template <int dim>
  std::vector<double>
  ContourProblem<dim>::target_on(
    const HuffmanLabeling::LabelingGrid<dim> &target_grid) const
  {
    if (parameters.target.is_image())
      return HuffmanLabeling::labeling_of_image(target_image.gray,
                                                target_image.nx,
                                                target_image.ny,
                                                parameters.target.maximum_label,
                                                target_grid,
                                                "Target / Image file");
    const std::unique_ptr<Function<dim>> distance =
      Shapes::create_signed_distance<dim>(parameters.target.shape);
    const Shapes::PhaseFieldProfile<dim> phase_field(
      *distance, this->level_parameters.model.epsilon);
    return HuffmanLabeling::labeling_of_function(phase_field,
                                                 target_grid,
                                                 this->mpi_communicator);
  }



  template <int dim>
  Vector
  ContourProblem<dim>::ghosted_u(const BlockVector &state) const
  {
    const LumpedOperators<dim> &ops = this->discretization.get_operators();
    Vector                      u(ops.locally_owned_dofs,
             ops.locally_relevant_dofs,
             this->mpi_communicator);
    u = state.block(0);
    return u;
  }



  template <int dim>
  typename MismatchTerm<dim>::Evaluation
  ContourProblem<dim>::mismatch(const BlockVector &state) const
  {
    return mismatch_term->evaluate(state.block(0));
  }



  template <int dim>
  StepReport
  ContourProblem<dim>::advance(TimeSteppingScheme<dim> &scheme,
                               const BlockVector       &old_state,
                               BlockVector             &state,
                               const double             tau)
  {
    if (parameters.time_stepping.coupling == ContourCoupling::monolithic)
      {
        // one nested step with the mismatch in its outer energy
        // (scheme_outer_energy()); the time loop checks its energy law
        unfinished_sub_step     = {SubStep::monolithic_step, tau};
        const StepReport report = scheme.advance(old_state, state, tau);
        if (report.converged)
          unfinished_sub_step.reset();
        return report;
      }
    // the time loop prepares P for the nested sub-steps (sub_step_size())
    const double half      = sub_step_size(tau);
    unfinished_sub_step    = {SubStep::first_nested_step, tau};
    const StepReport first = scheme.advance(old_state, state, half);
    if (!first.converged)
      return first;
    unfinished_sub_step = {SubStep::mismatch_step, tau};
    {
      TimerOutput::Scope t(this->computing_timer, "labeling: mismatch step");
      mismatch_step(state, tau);
    }
    // collective: the norm is that of all ranks
    if (!std::isfinite(state.block(0).l2_norm()))
      {
        StepReport failed = first;
        failed.converged  = false;
        return failed;
      }
    unfinished_sub_step      = {SubStep::second_nested_step, tau};
    const BlockVector middle = state;
    const StepReport  second = scheme.advance(middle, state, half);
    if (second.converged)
      unfinished_sub_step.reset();
    return combine(first, second);
  }



  template <int dim>
  void
  ContourProblem<dim>::mismatch_step(BlockVector &state, const double tau) const
  {
    Vector gradient(state.block(0));
    gradient = 0;
    mismatch_term->add_gradient(state.block(0), 1., gradient);
    // eps M (U - U^{k+1/3}) = -tau G with the lumped mass M
    gradient.scale(this->discretization.get_operators().inverse_lumped_mass);
    state.block(0).add(-tau / this->level_parameters.model.epsilon, gradient);
    this->discretization.get_constraints().distribute(state.block(0));
  }



  template <int dim>
  double
  ContourProblem<dim>::next_step_size(const double scheduled) const
  {
    last_scheduled = scheduled;
    return parameters.time_stepping.step_size_control ? tau_factor * scheduled :
                                                        scheduled;
  }



  template <int dim>
  double
  ContourProblem<dim>::merit(const BlockVector &state,
                             const Energies    &energies) const
  {
    return Constants::geometric_unit *
           total_energy(energies, mismatch(state).energy);
  }



  template <int dim>
  void
  ContourProblem<dim>::step_accepted(const unsigned int step,
                                     const BlockVector &old_state,
                                     const Energies    &old_energies,
                                     const BlockVector &state,
                                     const Energies    &energies,
                                     const StepReport  &report,
                                     const double       tau,
                                     const double       tried_tau)
  {
    (void)step;
    if (!parameters.time_stepping.step_size_control)
      return;
    // in units of the scheduled size (Tau, or a ramp-up size) that the
    // step's size was made from
    const double         level_tau = last_scheduled;
    const StepSizeLimits limits{min_tau_factor,
                                parameters.time_stepping.largest_tau_factor};
    double               factor = 1;
    if (tau >= tried_tau)
      {
        const double decrease =
          merit(old_state, old_energies) - merit(state, energies);
        const double dissipation =
          this->scheme->dissipation(old_state, state, tau);
        const bool easy =
          report.newton_iterations <= parameters.time_stepping.easy_iterations;
        factor = easy && decrease >= 2 * dissipation ? step_growth : 1;
        if (this->willmore_parameters.output.verbose)
          this->pcout << "  step size control: decrease " << decrease
                      << ", dissipation " << dissipation << ", "
                      << report.newton_iterations << " Newton iterations";
      }
    else if (this->willmore_parameters.output.verbose)
      this->pcout << "  step size control: the step was halved";
    tau_factor = limits.next(tau / level_tau, tried_tau / level_tau, factor);
    if (this->willmore_parameters.output.verbose)
      this->pcout << ": next tau = " << tau_factor << " Tau" << std::endl;
  }



  template <int dim>
  double
  ContourProblem<dim>::total_energy(const Energies &energies,
                                    const double    j) const
  {
    return weighted_regularisation(this->setup.outer_energy, energies) /
             Constants::geometric_unit +
           j;
  }



  template <int dim>
  bool
  ContourProblem<dim>::finished(const unsigned int step,
                                const BlockVector &state,
                                const Energies    &energies)
  {
    (void)step;
    if (parameters.multilevel.transition != LevelTransition::automatic)
      return false;
    const auto m = mismatch(state);
    const bool labeling =
      parameters.multilevel.criterion == TransitionCriterion::labeling_error;
    criterion_history.push_back(labeling ? m.labeling_error :
                                           total_energy(energies, m.energy));
    const unsigned int window = parameters.multilevel.window;
    if (criterion_history.size() <= window)
      return false;
    const double now = criterion_history.back();
    const double decrease =
      criterion_history[criterion_history.size() - 1 - window] - now;
    if (decrease >= parameters.multilevel.tolerance * std::abs(now))
      return false;
    this->pcout << (labeling ? "  labeling error" : "  total energy")
                << " decreased by " << decrease << " over " << window
                << " steps: moving on (Multilevel / Transition = automatic)"
                << std::endl;
    return true;
  }



  template <int dim>
  std::vector<std::string>
  ContourProblem<dim>::extra_columns() const
  {
    return {"level", "mismatch_energy", "labeling_error", "total_energy"};
  }



  template <int dim>
  std::vector<double>
  ContourProblem<dim>::extra_values(const BlockVector &state,
                                    const Energies    &energies) const
  {
    const auto m = mismatch(state);
    return {double(this->level_parameters.mesh.finest_level),
            m.energy,
            m.labeling_error,
            total_energy(energies, m.energy)};
  }



  template <int dim>
  void
  ContourProblem<dim>::write_level_results(const bool last_level)
  {
    TimerOutput::Scope t(this->computing_timer, "output: labelings");
    const unsigned int level_number = mismatch_term->grid().level();
    const HuffmanLabeling::LabelingGrid<dim> centres(level_number, true);
    ContourOutput::Labelings<dim>            labelings{
      centres,
      target_on(centres),
      HuffmanLabeling::labeling(this->discretization.get_dof_handler(),
                                ghosted_u(this->solution),
                                centres)};
    const std::string directory = this->willmore_parameters.output_directory;
    const std::string level     = std::to_string(level_number);
    ContourOutput::write_csv(labelings,
                             directory + "/labeling_level_" + level + ".csv",
                             this->mpi_communicator);
    if (last_level)
      ContourOutput::write_csv(labelings,
                               directory + "/labeling.csv",
                               this->mpi_communicator);
    ContourOutput::write_vtu(labelings,
                             directory + "/labeling_level_" + level + ".vtu",
                             this->mpi_communicator);
    ContourOutput::write_picture(labelings,
                                 this->discretization,
                                 this->solution.block(0),
                                 directory + "/contour_level_" + level +
                                   ".png");
    if constexpr (dim == 3)
      {
        // the continuous Q1 field: hanging nodes on their constraints
        Vector u = this->solution.block(0);
        this->discretization.get_constraints().distribute(u);
        ContourOutput::write_body_picture(
          labelings,
          this->discretization.get_dof_handler(),
          this->discretization.ghosted_copy(u),
          directory + "/body_level_" + level + ".png");
      }
  }



  template class ContourProblem<2>;
  template class ContourProblem<3>;
} // namespace PhaseField
