#pragma once
// The loop that steps an ensemble of runs to their ends (rodsea run, one run or several): in
// runs of steps sized to the progress reports, each run's frames, checkpoints, blow-ups, stops
// and steady ends decided by its RunSession, the threads following the free cores, the progress
// following the run with the most steps left.
#include <cstddef>
#include <ostream>
#include <vector>

#include "rodsea/cli/progress.hpp"
#include "rodsea/engine/ensemble.hpp"
#include "rodsea/run/run_session.hpp"

namespace rodsea {

// Steps every system of `ensemble` whose session started (`by_system[m]`, not null) to its
// run's end; the systems of the others leave first. `run_of[m]` is system m's place in
// `codes`, which receives each run's exit code. `threads`: at most this many (fewer while other
// processes take cores); `name_runs`: every message begins with its run's directory.
void step_to_the_end(Ensemble& ensemble, const std::vector<RunSession*>& by_system,
                     const std::vector<std::size_t>& run_of, std::vector<int>& codes, int threads,
                     bool name_runs, ProgressStyle style, std::ostream& out, std::ostream& err);

}  // namespace rodsea
