#include "rodsea/engine/work_shares.hpp"

#include <algorithm>
#include <numeric>

namespace rodsea {

std::size_t workers_side_by_side(std::size_t threads, std::size_t systems) {
    if (systems < 2 || threads >= 2 * systems) return 1;
    return std::min(threads, systems);
}

WorkShares share_by_cost(const std::vector<double>& costs, std::size_t workers) {
    WorkShares shares(std::max<std::size_t>(workers, 1));
    std::vector<std::size_t> by_cost(costs.size());
    std::iota(by_cost.begin(), by_cost.end(), std::size_t{0});
    std::stable_sort(by_cost.begin(), by_cost.end(),
                     [&](std::size_t a, std::size_t b) { return costs[a] > costs[b]; });
    std::vector<double> load(shares.size(), 0.0);
    for (const std::size_t m : by_cost) {
        const auto least =
            static_cast<std::size_t>(std::min_element(load.begin(), load.end()) - load.begin());
        shares[least].push_back(m);
        load[least] += costs[m];
    }
    return shares;
}

double busiest_share(const WorkShares& shares, const std::vector<double>& costs) {
    double busiest = 0.0;
    for (const std::vector<std::size_t>& share : shares) {
        double load = 0.0;
        for (const std::size_t m : share)
            load += costs[m];
        busiest = std::max(busiest, load);
    }
    return busiest;
}

std::optional<WorkShares> better_deal(const WorkShares& current, const std::vector<double>& costs,
                                      double worth) {
    WorkShares dealt = share_by_cost(costs, current.size());
    if (busiest_share(dealt, costs) < worth * busiest_share(current, costs)) return dealt;
    return std::nullopt;
}

}  // namespace rodsea
