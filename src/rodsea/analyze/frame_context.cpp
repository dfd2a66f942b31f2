#include "rodsea/analyze/frame_context.hpp"

#include "rodsea/analysis/neighbor_query.hpp"

namespace rodsea {

FrameContext::FrameContext(const AnalysisFrame& frame, std::span<const SpeciesInfo> species,
                           bool steady, int block)
    : frame_(frame), species_(species), steady_(steady), block_(block) {}

bool FrameContext::in(BodyGroup group, std::uint32_t body) const {
    const BodyKind kind = species_[frame_.species[body]].kind;
    switch (group) {
        case BodyGroup::polar:
            return kind == BodyKind::polar_rod;
        case BodyGroup::medium:
            return kind != BodyKind::polar_rod;
        case BodyGroup::medium_rods:
            return kind == BodyKind::apolar_rod;
        case BodyGroup::all:
            return true;
    }
    return false;
}

const GroupArrays& FrameContext::group(BodyGroup group) const {
    auto& slot = groups_[static_cast<std::size_t>(group)];
    if (!slot) {
        slot = std::make_unique<GroupArrays>();
        for (std::uint32_t i = 0; i < frame_.size(); ++i) {
            if (!in(group, i)) continue;
            slot->members.push_back(i);
            slot->position.push_back(frame_.position[i]);
            slot->angle.push_back(frame_.theta[i]);
            slot->velocity.push_back(frame_.velocity[i]);
        }
        slot->grid.build(slot->position, frame_.box, kQueryCell);
    }
    return *slot;
}

}  // namespace rodsea
