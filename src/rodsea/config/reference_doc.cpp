// config_reference_markdown(): docs/config.md, generated from the key table so that the docs
// cannot drift from the code (tests/test_config.cpp compares the committed file).
#include <sstream>

#include "rodsea/config/config_file.hpp"
#include "rodsea/config/schema.hpp"

namespace rodsea {

namespace {

using config::KeySpec;
using config::TableSpec;

std::string kinds_text(config::KindMask kinds) {
    std::string s;
    for (const BodyKind k : {BodyKind::polar_rod, BodyKind::apolar_rod, BodyKind::bead})
        if (kinds & config::kind_bit(k)) s += (s.empty() ? "" : ", ") + std::string(to_string(k));
    return s;
}

std::string description(const KeySpec& k) {
    std::string s = k.doc;
    if (k.kinds != config::kAllKinds) s += " Only for " + kinds_text(k.kinds) + ".";
    if (!k.alternative.empty()) s += " Excludes `" + k.alternative + "`.";
    if (!k.choice.empty()) {
        s += " **CHOICE**";
        if (k.choice_kinds != config::kAllKinds) s += " (" + kinds_text(k.choice_kinds) + ")";
        s += ": " + k.choice + ".";
    }
    return s;
}

std::string header(const TableSpec& t) {
    return t.array ? "[[" + t.path + "]]" : "[" + t.path + "]";
}

}  // namespace

std::string config_reference_markdown() {
    std::ostringstream md;
    md << "# Config file reference\n\n"
          "<!-- Generated from the key table (src/rodsea/config/schema.cpp) by\n"
          "     config_reference_markdown(). Do not edit: regenerate with\n"
          "     `rodsea config --reference > docs/config.md`. -->\n\n"
          "A run is one TOML file. Every key has a default except the few marked required, so "
          "an empty file is the paper's main system (polar rods at φ_p = 0.05 in apolar rods of "
          "ℓ_a = 2.5 mm at φ_a = 0.50, L = 252 mm, Γ = 7 at 200 Hz) for 1 s. Units are mm, s and "
          "an arbitrary mass unit. Integers are accepted where reals are expected, not the "
          "other way round. Two keys of one table that say the same thing (`side` and "
          "`side_in_polar_lengths`) exclude each other.\n\n"
          "The whole file is checked before anything runs: an unknown key, a wrong type or a "
          "value out of range is an error naming the key's full path (`drive.gamma`, "
          "`species[1].length`, counting [[species]] from 0), the value and what is allowed, "
          "with a suggestion for a misspelt key. A run stores the resolved config (every key "
          "with its value) in its outputs, and lists the CHOICEs in force.\n\n"
          "**CHOICE** marks a default that docs/model.md chose where the paper is silent or "
          "inconsistent; each is listed at the end.\n\n"
          "The examples in `examples/` reproduce the paper's figure families.\n";
    for (const TableSpec& t : config::config_tables()) {
        md << "\n## " << header(t) << "\n\n" << t.doc << "\n\n";
        md << "| key | type | unit | default | allowed | description |\n"
              "|---|---|---|---|---|---|\n";
        for (const KeySpec* k : config::keys_of(t.path)) {
            md << "| `" << k->name << "` | " << k->type_text() << " | "
               << config::markdown_cell(k->unit.empty() ? "—" : k->unit) << " | "
               << config::markdown_cell(k->default_doc()) << " | "
               << config::markdown_cell(k->allowed_text()) << " | "
               << config::markdown_cell(description(*k)) << " |\n";
        }
    }
    md << "\n## CHOICEs\n\n| key | default | why |\n|---|---|---|\n";
    for (const KeySpec& k : config::config_keys()) {
        if (k.choice.empty()) continue;
        std::string key = "`";
        key += k.path();
        key += "`";
        if (k.choice_kinds != config::kAllKinds) key += " (" + kinds_text(k.choice_kinds) + ")";
        std::string default_text = k.default_doc();
        if (k.default_value && !k.unit.empty()) default_text += " " + k.unit;
        md << "| " << key << " | " << config::markdown_cell(default_text) << " | "
           << config::markdown_cell(k.choice) << " |\n";
    }
    md << "| sphere-chain construction | — | equally spaced centres, the end centres one end "
          "radius inside the rod's ends, each diameter the profile's at its centre: reproduces "
          "the paper's Table S1 counts; docs/model.md §2 |\n";
    return md.str();
}

}  // namespace rodsea
