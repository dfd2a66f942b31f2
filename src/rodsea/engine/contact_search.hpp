#pragma once
// Stage 3 of the step: every sphere–sphere overlap between different bodies (minimum image in
// x, y) and every sphere poking through the base or the lid. Contact points sit in the middle
// of the overlap.
#include <vector>

#include "rodsea/engine/contact.hpp"
#include "rodsea/engine/parameters.hpp"
#include "rodsea/engine/plates.hpp"
#include "rodsea/engine/sphere_table.hpp"
#include "rodsea/neighbors/periodic_cell_list.hpp"

namespace rodsea {

struct ContactSearchStats {
    size_t body_contacts = 0;
    size_t plate_contacts = 0;
    double max_overlap_fraction = 0.0;  // overlap / smaller radius, largest in this step
};

ContactSearchStats find_contacts(const SphereTable& spheres, const BodyState& bodies,
                                 const EngineParameters& params, const PlateState& plates,
                                 PeriodicCellList2D& cells, std::vector<Contact>& out);

}  // namespace rodsea
