#pragma once
// The option tables more than one subcommand binds: the forces of SimulationParameters
// (pack and animate) and the run's seed and threads.
#include <cstdint>

#include "option_table.hpp"
#include "pak/sim/run_options.hpp"
#include "pak/sim/simulation_parameters.hpp"

namespace pak::cli {

const OptionTable<SimulationParameters>& simulationOptions();
const OptionTable<RunOptions>& runOptions();

// --seed alone, for options without a RunOptions.
template <class Root>
Option<Root> seedOption(Field<Root, std::uint64_t> seed) {
  return {"seed", std::move(seed), "random seed; the same seed gives the same result"};
}

}  // namespace pak::cli
