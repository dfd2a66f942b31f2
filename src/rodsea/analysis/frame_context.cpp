#include "rodsea/analysis/frame_context.hpp"

namespace rodsea {

FrameContext::FrameContext(const AnalysisFrame& frame, std::span<const SpeciesInfo> species,
                           bool steady, double cell_side)
    : frame_(frame), species_(species), steady_(steady), cell_side_(cell_side) {}

const BodyGrid& FrameContext::grid(BodyGroup group) const {
    auto& slot = grids_[static_cast<std::size_t>(group)];
    if (!slot) {
        std::vector<std::uint32_t> members;
        for (std::uint32_t i = 0; i < frame_.size(); ++i) {
            const bool polar = is_polar(i);
            if (group == BodyGroup::all || (group == BodyGroup::polar) == polar)
                members.push_back(i);
        }
        slot = std::make_unique<BodyGrid>();
        slot->build(frame_, std::move(members), cell_side_);
    }
    return *slot;
}

}  // namespace rodsea
