#pragma once
// How an ensemble's CPU systems are dealt to its workers (ensemble.hpp): one step of the
// ensemble lasts as long as its busiest worker, so the systems are dealt by what a step of each
// costs, the costliest first, each to the worker with the least so far (longest processing time
// first: within 4/3 of the best split, and the best for three systems on two workers).
#include <cstddef>
#include <vector>

namespace rodsea {

// max(workers, 1) lists of indices into `costs`, each costliest first (as dealt); equal costs
// are dealt in index order, so the same costs give the same shares.
std::vector<std::vector<std::size_t>> share_by_cost(const std::vector<double>& costs,
                                                    std::size_t workers);

// The busiest worker's total cost under `shares`: what one step of the ensemble takes.
double busiest_share(const std::vector<std::vector<std::size_t>>& shares,
                     const std::vector<double>& costs);

}  // namespace rodsea
