#pragma once
// ConfigValues (as given) → RunPlan: fills in every default, checks the keys against each other
// and builds the engine's parameters, counts and controls.
#include "rodsea/config/config_file.hpp"
#include "rodsea/config/config_values.hpp"
#include "rodsea/config/run_plan.hpp"

namespace rodsea::config {

// On return `values` holds every key in force (defaults included, one of each pair of
// alternatives) and the equivalents of the alternatives not used. The plan's config_toml and
// choices are left empty. `epsilon` turns noise.rotational_diffusion into ε. Throws
// InvalidParameter naming the first bad key.
RunPlan resolve(ConfigValues& values, const EpsilonLookup& epsilon);

// Throws when both keys of a pair of alternatives (box.side, box.side_in_polar_lengths) are
// given, naming the one that comes second in the schema.
void check_alternatives(const TableValues& t, std::string_view table, const std::string& source);

// The paper's main system (docs/model.md §2), what a config without [[species]] simulates: polar
// rods at φ_p = 0.05 named "polar" in apolar rods of ℓ_a = 2.5 mm at φ_a = 0.50 named "medium".
std::vector<TableValues> default_species();

// "polar_rod" → BodyKind::polar_rod; the value was checked against the schema's options.
BodyKind parse_kind(const std::string& kind);

// [[species]] tables: defaults by kind, checks within one table, the Species they describe.
void complete_species(TableValues& species, const std::string& source);
Species make_species(const TableValues& species);
double apolar_length(const TableValues& species);  // mm, from length or aspect_ratio

}  // namespace rodsea::config
