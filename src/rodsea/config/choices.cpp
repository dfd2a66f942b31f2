#include "rodsea/config/detail/choices.hpp"

#include "rodsea/config/detail/resolve.hpp"
#include "rodsea/config/schema.hpp"
#include "rodsea/error.hpp"

namespace rodsea::config {

namespace {

std::string line(const std::string& path, const KeySpec& spec, const Value& value,
                 const std::optional<Value>& default_value, const std::string& context) {
    std::string status = "CHOICE";
    if (default_value && *default_value == value)
        status = "the CHOICE default";
    else if (default_value)
        status = "overrides the CHOICE default " + spec.shown(*default_value);
    return path + " = " + spec.shown(value) + " (" + context + status + "; " + spec.choice + ")";
}

}  // namespace

std::vector<std::string> list_choices(const ConfigValues& c, const RunPlan& plan) {
    bool any_polar = false, any_rod = false;
    for (const Species& s : plan.engine.species) {
        any_polar = any_polar || s.kind == BodyKind::polar_rod;
        any_rod = any_rod || s.kind != BodyKind::bead;
    }
    std::vector<std::string> lines;
    for (const TableSpec& table : config_tables()) {
        for (const TableValues& t : c.all(table.path)) {
            for (const KeySpec* spec : keys_of(table.path)) {
                if (spec->choice.empty() || !t.has(spec->name)) continue;
                if (table.path == "species") {
                    const BodyKind kind = parse_kind(t.text("kind"));
                    if (!spec->is_choice_for(kind)) continue;
                    const double length = kind == BodyKind::apolar_rod ? apolar_length(t) : 0.0;
                    lines.push_back(
                        line(t.key_path(spec->name), *spec, t.at(spec->name),
                             species_default(spec->name, kind, length),
                             std::string(to_string(kind)) + " '" + t.text("name") + "'; "));
                    continue;
                }
                // The form of the noise kick matters only where there are polar rods to kick.
                if (spec->path() == "noise.epsilon" && !any_polar) continue;
                lines.push_back(
                    line(t.key_path(spec->name), *spec, t.at(spec->name), spec->default_value, ""));
            }
        }
    }
    if (any_rod) {
        lines.push_back(
            "sphere chains: equally spaced centres, the end centres one end radius inside the "
            "rod's ends, each diameter the profile's at its centre (CHOICE: reproduces the "
            "paper's Table S1 counts; docs/model.md §2)");
    }
    return lines;
}

}  // namespace rodsea::config
