#pragma once
// How an ensemble's CPU systems are dealt to its workers (ensemble.hpp): one step of the
// ensemble lasts as long as its busiest worker, so the systems are dealt by what a step of each
// costs, the costliest first, each to the worker with the least so far (longest processing time
// first: within 4/3 of the best split, and the best for three systems on two workers).
#include <cstddef>
#include <optional>
#include <vector>

namespace rodsea {

using WorkShares = std::vector<std::vector<std::size_t>>;

// How many workers step `systems` side by side on `threads`, one thread each: min(threads,
// systems), or 1 when there is one system or at least two threads for each (side by side would
// then nest OpenMP teams, which libgomp starts afresh at every region: the systems take turns,
// each on every thread).
std::size_t workers_side_by_side(std::size_t threads, std::size_t systems);

// max(workers, 1) lists of indices into `costs` (finite, >= 0), each costliest first (as dealt);
// equal costs are dealt in index order, so the same costs give the same shares.
WorkShares share_by_cost(const std::vector<double>& costs, std::size_t workers);

// The busiest worker's total cost under `shares`: what one step of the ensemble takes.
double busiest_share(const WorkShares& shares, const std::vector<double>& costs);

// The deal by `costs` on as many workers as `current` has, if it makes the busiest worker's
// load less than `worth` times what it is under `current`; else nothing. A system that changes
// workers loses its caches, and costs measured over a window jitter: a deal that gains less than
// that is not worth making.
std::optional<WorkShares> better_deal(const WorkShares& current, const std::vector<double>& costs,
                                      double worth);

}  // namespace rodsea
