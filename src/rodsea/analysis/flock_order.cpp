#include "rodsea/analysis/flock_order.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace rodsea {

double independent_flock_order(std::span<const double> angles, std::span<const int> labels) {
    if (angles.size() != labels.size())
        throw std::invalid_argument("independent_flock_order: one label per angle needed");
    if (angles.empty()) return 0.0;
    std::vector<double> cx, cy;  // m_k per flock
    double squared = 0.0;
    for (std::size_t i = 0; i < angles.size(); ++i) {
        if (labels[i] < 0) {
            squared += 1.0;
            continue;
        }
        const auto k = static_cast<std::size_t>(labels[i]);
        if (k >= cx.size()) {
            cx.resize(k + 1, 0.0);
            cy.resize(k + 1, 0.0);
        }
        cx[k] += std::cos(angles[i]);
        cy[k] += std::sin(angles[i]);
    }
    for (std::size_t k = 0; k < cx.size(); ++k)
        squared += cx[k] * cx[k] + cy[k] * cy[k];
    return std::sqrt(squared) / static_cast<double>(angles.size());
}

}  // namespace rodsea
