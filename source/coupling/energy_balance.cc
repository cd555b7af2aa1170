// The energy balance of a scene with inertia: the points' energies and
// dissipation, the work from outside, the check after every step.
#include <impm/base/errors.h>
#include <impm/core/point_properties.h>
#include <impm/coupling/energy_balance.h>
#include <impm/mechanics/material.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>

namespace impm
{
  template <int dim>
  void
  EnergyBalance<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Energy balance tolerance",
      "0.05",
      Patterns::Double(0.),
      "The largest error of the energy balance, kinetic plus elastic plus "
      "dissipated energy against the initial energy plus the work from "
      "outside (loads, moving faces, springs, dashpots, contacts, a shaken "
      "base), as a fraction of the run's largest energy, before a line "
      "reports it (again each time it has doubled). The error is written "
      "after every step (steps.csv's energy_error; in explicit steps that "
      "at the step's start, with the mean of the half steps' velocities "
      "around it); it measures the time integration (the kinetic energy the "
      "transfer between points and nodes takes out is written apart, "
      "transfer_loss).");
    prm.declare_entry(
      "Energy growth limit",
      "10",
      Patterns::Double(0.),
      "The run stops with an error when the points hold more energy than "
      "was put in by more than this many times the most energy put in so "
      "far, and by more at each of three steps in a row: their kinetic "
      "plus elastic plus dissipated energy above the initial energy plus "
      "the work from outside. A stable integration "
      "makes no energy (it loses some to its numerical dissipation and the "
      "transfer between points and nodes, which never stops a run); "
      "energy made from nothing is an integration gone unstable (explicit "
      "USL where points enter cells their neighbours do not fill), and its "
      "answer is wrong. 0: never stop.");
  }



  template <int dim>
  EnergyBalance<dim>::EnergyBalance(const ParameterHandler &prm,
                                    const MPI_Comm          communicator,
                                    const bool              staggered)
    : tolerance(prm.get_double("Energy balance tolerance"))
    , growth_limit(prm.get_double("Energy growth limit"))
    , communicator(communicator)
    , staggered(staggered)
  {}



  template <int dim>
  void
  EnergyBalance<dim>::start(const MaterialPoints<dim> &material_points,
                            const PointSteps<dim>     &steps)
  {
    if (started)
      return;
    const unsigned int velocity_first =
      material_points.layout().coupling_field("velocity");
    double local_kinetic = 0., local_elastic = 0.;
    for (const auto &point : material_points.particles())
      {
        const auto            properties = point.get_properties();
        const PointState<dim> state(properties);
        for (unsigned int i = 0; i < dim; ++i)
          local_kinetic += 0.5 * state.mass() * properties[velocity_first + i] *
                           properties[velocity_first + i];
        // The stored energy as the material's update gives it for no
        // motion (a pressure-dependent elasticity's own), else from the
        // stress and the elastic strain.
        const PointStep<dim> &step = steps.of(point);
        ConstitutiveUpdate    update;
        try
          {
            step.material->update(static_cast<Tensor<2, 3>>(
                                    unit_symmetric_tensor<3>()),
                                  state.elastic_left_cauchy_green(),
                                  material_points.material_state(properties),
                                  update);
          }
        catch (const ExceptionBase &)
          {
            update = ConstitutiveUpdate();
          }
        update.kirchhoff_stress          = state.kirchhoff_stress();
        update.elastic_left_cauchy_green = state.elastic_left_cauchy_green();
        local_elastic += step.initial_volume * elastic_energy_density(update);
      }
    initial_kinetic = Utilities::MPI::sum(local_kinetic, communicator);
    initial_elastic = Utilities::MPI::sum(local_elastic, communicator);
    kinetic         = initial_kinetic;
    elastic         = initial_elastic;
    largest_energy  = std::abs(initial_kinetic + initial_elastic);
    largest_input   = largest_energy;
    started         = true;
  }



  template <int dim>
  void
  EnergyBalance<dim>::take(const StepEnergy &energy)
  {
    step_energy = energy;
  }



  template <int dim>
  void
  EnergyBalance<dim>::accept(const MaterialPoints<dim> &material_points,
                             const PointSteps<dim>     &steps,
                             const std::vector<double> &velocities,
                             const double local_damping_dissipation,
                             const NodalKineticEnergy &local_nodal_kinetic,
                             const double              start_time,
                             const double              end_time)
  {
    const unsigned int velocity_first =
      material_points.layout().coupling_field("velocity");
    double local_kinetic = 0., local_elastic = 0., local_plastic = 0.,
           local_mean_kinetic = 0.;
    for (const auto &point : material_points.particles())
      {
        const unsigned int    p          = steps.index_of(point);
        const PointStep<dim> &step       = steps[p];
        const auto            properties = point.get_properties();
        const PointState<dim> state(properties);
        local_elastic +=
          step.initial_volume * elastic_energy_density(step.update);
        if (step.update.plastic)
          local_plastic +=
            step.initial_volume * plastic_dissipation_density(step.update);
        for (unsigned int i = 0; i < dim; ++i)
          {
            const double v = velocities[p * dim + i];
            local_kinetic += 0.5 * state.mass() * v * v;
            if (staggered)
              {
                // The points still hold the velocity before the step.
                const double mean = 0.5 * (v + properties[velocity_first + i]);
                local_mean_kinetic += 0.5 * state.mass() * mean * mean;
              }
          }
      }
    if (staggered)
      {
        // The balance at the step's start, from the sums up to it.
        const double mean_kinetic =
          Utilities::MPI::sum(local_mean_kinetic, communicator);
        largest_energy = std::max(largest_energy, mean_kinetic);
        const double balance =
          half_step_velocities ? balance_error(mean_kinetic) : 0.;
        start_error = largest_energy > 0. ? balance / largest_energy : 0.;
        // No balance before the first half step: nothing to judge.
        error_energy         = half_step_velocities ?
                                 balance - transfer_loss :
                                 std::numeric_limits<double>::quiet_NaN();
        error_time           = start_time;
        half_step_velocities = true;
      }
    const double start_kinetic = kinetic;
    kinetic = Utilities::MPI::sum(local_kinetic, communicator);
    transfer_loss +=
      start_kinetic - kinetic +
      Utilities::MPI::sum(local_nodal_kinetic.end - local_nodal_kinetic.start,
                          communicator);
    elastic = Utilities::MPI::sum(local_elastic, communicator);
    plastic_dissipation += Utilities::MPI::sum(local_plastic, communicator);
    other_dissipation +=
      Utilities::MPI::sum(local_damping_dissipation, communicator) +
      step_energy.dissipated;
    external_work += step_energy.external_work;
    step_energy             = StepEnergy();
    const double dissipated = plastic_dissipation + other_dissipation;
    largest_energy          = std::max({largest_energy,
                                        kinetic,
                                        std::abs(elastic),
                                        std::abs(external_work),
                                        std::abs(dissipated),
                                        std::abs(transfer_loss)});
    largest_input =
      std::max(largest_input,
               std::abs(initial_kinetic + initial_elastic + external_work));
    if (!staggered)
      {
        error_energy = balance_error(kinetic) - transfer_loss;
        error_time   = end_time;
      }
    growth_before      = {growth_before[1], growth};
    growth             = largest_input > 0. && !std::isnan(error_energy) ?
                           error_energy / largest_input :
                           std::numeric_limits<double>::infinity();
    const double error = std::abs(relative_error());
    if (error > tolerance && error >= 2. * reported_error)
      {
        reported_error = error;
        if (Utilities::MPI::this_mpi_process(communicator) == 0)
          std::cerr << "Warning: at t = " << (staggered ? start_time : end_time)
                    << " s the energy balance is off by " << 100. * error
                    << " % of the run's largest energy (kinetic + elastic + "
                       "dissipated against the initial energy + the work "
                       "from outside; 'Energy balance tolerance' "
                    << 100. * tolerance
                    << " %): the time step, the transfer between points "
                       "and nodes, or an effect whose energy is not "
                       "accounted."
                    << std::endl;
      }
  }



  template <int dim>
  double
  EnergyBalance<dim>::relative_error() const
  {
    if (staggered)
      return start_error;
    if (!(largest_energy > 0.))
      return 0.;
    return balance_error(kinetic) / largest_energy;
  }



  template <int dim>
  std::string
  EnergyBalance<dim>::unstable_growth() const
  {
    // Growing over three steps: a start whose work lags its motion (a face
    // pulled from rest: 8.5 times its tiny work after the first step)
    // falls back as the work grows; an instability keeps growing.
    if (!(growth_limit > 0.) || !(growth > growth_limit) ||
        !(growth > growth_before[1] && growth_before[1] > growth_before[0]))
      return "";
    std::ostringstream message;
    message << std::setprecision(3) << "At t = " << error_time
            << " s the points hold " << error_energy
            << " J more than was put in, " << std::fixed << std::setprecision(2)
            << growth << std::defaultfloat << std::setprecision(3)
            << " times the most energy put in so far (" << largest_input
            << " J, the initial energy plus the work from outside; "
               "'Inertia/Energy growth limit' = "
            << growth_limit
            << "): the time integration has become unstable and its "
               "answer is wrong (a time step too large for the scene, or "
               "explicit USL where points enter cells their neighbours do "
               "not fill: use explicit MUSL).";
    return message.str();
  }



  template <int dim>
  double
  EnergyBalance<dim>::balance_error(const double kinetic_energy) const
  {
    return (kinetic_energy - initial_kinetic) + (elastic - initial_elastic) +
           plastic_dissipation + other_dissipation + transfer_loss -
           external_work;
  }



  template <int dim>
  std::vector<std::string>
  EnergyBalance<dim>::columns()
  {
    return {"kinetic_energy",
            "strain_energy",
            "total_energy",
            "external_work",
            "dissipated_energy",
            "transfer_loss",
            "energy_error"};
  }



  template <int dim>
  void
  EnergyBalance<dim>::add_measures(std::vector<StepMeasure> &measures) const
  {
    measures.push_back({"kinetic_energy", "Ek", kinetic, MeasureKind::energy});
    measures.push_back({"strain_energy", "Es", elastic, MeasureKind::energy});
    measures.push_back(
      {"total_energy", "E", kinetic + elastic, MeasureKind::energy});
    measures.push_back(
      {"external_work", "W", external_work, MeasureKind::energy});
    measures.push_back({"dissipated_energy",
                        "D",
                        plastic_dissipation + other_dissipation,
                        MeasureKind::energy});
    measures.push_back(
      {"transfer_loss", "T", transfer_loss, MeasureKind::energy});
    measures.push_back(
      {"energy_error", "dE", relative_error(), MeasureKind::number});
  }



  template <int dim>
  void
  EnergyBalance<dim>::save(RunState &state) const
  {
    state.set("energy balance",
              std::vector<double>{initial_kinetic,
                                  initial_elastic,
                                  kinetic,
                                  elastic,
                                  plastic_dissipation,
                                  other_dissipation,
                                  external_work,
                                  transfer_loss,
                                  largest_energy,
                                  reported_error,
                                  largest_input});
  }



  template <int dim>
  void
  EnergyBalance<dim>::load(const RunState &state)
  {
    const std::vector<double> values = state.get_list("energy balance");
    // Checkpoints before 'Energy growth limit' hold 10 values.
    if (values.size() != 10 && values.size() != 11)
      throw InputError("The checkpoint's 'energy balance' has " +
                       std::to_string(values.size()) +
                       " values, not 11: a damaged checkpoint.");
    initial_kinetic     = values[0];
    initial_elastic     = values[1];
    kinetic             = values[2];
    elastic             = values[3];
    plastic_dissipation = values[4];
    other_dissipation   = values[5];
    external_work       = values[6];
    transfer_loss       = values[7];
    largest_energy      = values[8];
    reported_error      = values[9];
    largest_input =
      values.size() == 11 ?
        values[10] :
        std::max(std::abs(initial_kinetic + initial_elastic),
                 std::abs(initial_kinetic + initial_elastic + external_work));
    started = true;
    // A resumed run's points carry the velocities of a half step.
    half_step_velocities = true;
  }



  template class EnergyBalance<2>;
  template class EnergyBalance<3>;
} // namespace impm
