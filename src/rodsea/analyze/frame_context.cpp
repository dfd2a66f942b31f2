#include "rodsea/analyze/frame_context.hpp"

#include <stdexcept>

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

const FrameFields& FrameContext::fields(double cell) const {
    const FieldGrid grid = FieldGrid::of(frame_.box, cell);
    if (fields_) {
        if (fields_->grid.nx != grid.nx || fields_->grid.ny != grid.ny)
            throw std::logic_error("FrameContext::fields: one cell size per frame");
        return *fields_;
    }
    fields_ = std::make_unique<FrameFields>();
    fields_->grid = grid;
    const double box_area = frame_.box.lx * frame_.box.ly;
    std::vector<Vec3> rod_position, rod_velocity;
    std::vector<double> rod_angle;
    for (std::uint32_t s = 0; s < species_.size(); ++s) {
        std::vector<Vec3> position, velocity;
        std::vector<double> angle;
        for (std::uint32_t i = 0; i < frame_.size(); ++i) {
            if (frame_.species[i] != s) continue;
            position.push_back(frame_.position[i]);
            angle.push_back(frame_.theta[i]);
            velocity.push_back(frame_.velocity[i]);
        }
        const SpeciesInfo& info = species_[s];
        const double body_area =
            info.count > 0 ? info.area_fraction * box_area / static_cast<double>(info.count) : 0.0;
        fields_->species.push_back(
            coarse_grain(grid, frame_.box, position, angle, velocity, body_area));
        if (info.kind == BodyKind::apolar_rod) {
            rod_position.insert(rod_position.end(), position.begin(), position.end());
            rod_angle.insert(rod_angle.end(), angle.begin(), angle.end());
            rod_velocity.insert(rod_velocity.end(), velocity.begin(), velocity.end());
        }
    }
    // Area fractions of the medium's rods together are not asked for: their areas may differ.
    if (!rod_position.empty())
        fields_->medium_rods =
            coarse_grain(grid, frame_.box, rod_position, rod_angle, rod_velocity, 0.0);
    return *fields_;
}

const std::vector<NematicDefect>& FrameContext::defects(double cell) const {
    const FrameFields& f = fields(cell);
    if (!defects_)
        defects_ = f.medium_rods
                       ? find_nematic_defects(f.grid, f.medium_rods->qxx, f.medium_rods->qxy)
                       : std::vector<NematicDefect>{};
    return *defects_;
}

const std::vector<int>& FrameContext::flock_labels(const DbscanParameters& parameters) const {
    if (!flock_labels_)
        flock_labels_ = dbscan(group(BodyGroup::polar).position, frame_.box, parameters);
    return *flock_labels_;
}

}  // namespace rodsea
