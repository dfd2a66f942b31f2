#include "rodsea/analysis/body_grid.hpp"

#include <stdexcept>

namespace rodsea {

void BodyGrid::build(const AnalysisFrame& frame, std::vector<std::uint32_t> members,
                     double cell_side) {
    if (!(cell_side > 0.0)) throw std::invalid_argument("BodyGrid: cell side must be positive");
    box_ = frame.box;
    nx_ = std::max(1, static_cast<int>(box_.lx / cell_side));
    ny_ = std::max(1, static_cast<int>(box_.ly / cell_side));
    wx_ = box_.lx / nx_;
    wy_ = box_.ly / ny_;
    members_ = std::move(members);
    const std::size_t cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
    std::vector<std::uint32_t> cell_of(members_.size());
    start_.assign(cells + 1, 0);
    for (std::size_t k = 0; k < members_.size(); ++k) {
        const std::uint32_t i = members_[k];
        const auto c = static_cast<std::uint32_t>(cell_index(frame.y[i], box_.ly, ny_) * nx_ +
                                                  cell_index(frame.x[i], box_.lx, nx_));
        cell_of[k] = c;
        ++start_[c + 1];
    }
    for (std::size_t c = 0; c < cells; ++c)
        start_[c + 1] += start_[c];
    std::vector<std::uint32_t> cursor(start_.begin(), start_.end() - 1);
    slot_body_.resize(members_.size());
    sx_.resize(members_.size());
    sy_.resize(members_.size());
    for (std::size_t k = 0; k < members_.size(); ++k) {
        const std::uint32_t s = cursor[cell_of[k]]++;
        const std::uint32_t i = members_[k];
        slot_body_[s] = i;
        sx_[s] = frame.x[i];
        sy_[s] = frame.y[i];
    }
}

}  // namespace rodsea
