// The [[species]] tables: what each kind of body accepts and defaults to, and the Species it
// builds (docs/model.md §2, with the sphere count and mass configurable).
#include <algorithm>

#include "rodsea/config/detail/resolve.hpp"
#include "rodsea/config/schema.hpp"
#include "rodsea/error.hpp"
#include "rodsea/shape/sphere_chain.hpp"

namespace rodsea::config {

namespace {

std::string kinds_text(KindMask kinds) {
    std::string s;
    for (const BodyKind k : {BodyKind::polar_rod, BodyKind::apolar_rod, BodyKind::bead})
        if (kinds & kind_bit(k)) s += (s.empty() ? "" : " and ") + std::string(to_string(k));
    return s;
}

// Names become column names, file names and plot labels: 64 characters is plenty.
constexpr std::size_t kMaxNameLength = 64;

bool valid_name(const std::string& name) {
    return !name.empty() && name.size() <= kMaxNameLength &&
           std::all_of(name.begin(), name.end(), [](char c) {
               return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '_' || c == '-';
           });
}

std::string at_table(const TableValues& t, const std::string& source) {
    return t.line > 0 ? "the table at " + source + " line " + std::to_string(t.line) : "";
}

}  // namespace

BodyKind parse_kind(const std::string& kind) {
    if (kind == "polar_rod") return BodyKind::polar_rod;
    if (kind == "apolar_rod") return BodyKind::apolar_rod;
    return BodyKind::bead;
}

double apolar_length(const TableValues& t) {
    return t.has("length") ? t.real("length") : t.real("aspect_ratio") * kApolarRodDiameter;
}

void complete_species(TableValues& t, const std::string& source) {
    const KeySpec& kind_spec = *find_key("species", "kind");
    if (!t.has("kind")) {
        throw InvalidParameter(t.key_path("kind"), "missing", kind_spec.allowed_text(),
                               join_why("every [[species]] needs a kind", at_table(t, source)));
    }
    const BodyKind kind = parse_kind(t.text("kind"));
    for (const auto& [key, entry] : t.entries) {
        const KeySpec& spec = *find_key("species", key);
        if (!(spec.kinds & kind_bit(kind))) {
            throw InvalidParameter(t.key_path(key), spec.shown(entry.value),
                                   "no " + key + " for a " + to_string(kind),
                                   join_why(key + " applies to " + kinds_text(spec.kinds) + " only",
                                            t.where(key, source)));
        }
    }
    check_alternatives(t, "species", source);
    if (kind == BodyKind::apolar_rod && !t.has("length") && !t.has("aspect_ratio")) {
        throw InvalidParameter(t.key_path("length"), "missing",
                               "length " + find_key("species", "length")->allowed_text() +
                                   " or aspect_ratio " +
                                   find_key("species", "aspect_ratio")->allowed_text(),
                               join_why("an apolar rod needs its length", at_table(t, source)));
    }
    if (!t.has("area_fraction") && !t.has("count")) {
        throw InvalidParameter(
            t.key_path("area_fraction"), "missing",
            "area_fraction " + find_key("species", "area_fraction")->allowed_text() +
                " or count >= 0",
            join_why("every [[species]] needs one of them", at_table(t, source)));
    }

    const double length = kind == BodyKind::apolar_rod ? apolar_length(t) : 0.0;
    for (const KeySpec* spec : keys_of("species")) {
        if (t.has(spec->name) || !(spec->kinds & kind_bit(kind))) continue;
        if (!spec->alternative.empty() && t.has(spec->alternative)) continue;
        if (auto v = species_default(spec->name, kind, length)) t.entries[spec->name] = {*v, 0};
    }

    if (!valid_name(t.text("name"))) {
        throw InvalidParameter(t.key_path("name"), toml_literal(t.at("name")),
                               find_key("species", "name")->allowed_text(),
                               join_why("a non-empty name of at most " +
                                            std::to_string(kMaxNameLength) + " characters",
                                        t.where("name", source)));
    }
    const std::int64_t spheres = t.integer("spheres");
    if (kind == BodyKind::polar_rod && spheres < 2) {
        throw InvalidParameter(
            t.key_path("spheres"), std::to_string(spheres),
            "an integer in [2, 200] for a polar_rod",
            join_why("a polar rod needs a thick and a thin end", t.where("spheres", source)));
    }
    if (kind == BodyKind::bead && spheres != 1) {
        throw InvalidParameter(t.key_path("spheres"), std::to_string(spheres), "1 for a bead",
                               join_why("a bead is one sphere", t.where("spheres", source)));
    }
}

Species make_species(const TableValues& t) {
    const BodyKind kind = parse_kind(t.text("kind"));
    const int spheres = static_cast<int>(t.integer("spheres"));
    const std::string& name = t.text("name");
    SphereList chain;
    switch (kind) {
        case BodyKind::polar_rod: {
            PolarRodGeometry g;
            g.sphere_count = spheres;
            chain = polar_rod_spheres(g);
            break;
        }
        case BodyKind::apolar_rod: {
            ApolarRodGeometry g = ApolarRodGeometry::with_length(apolar_length(t));
            g.sphere_count = spheres;
            chain = apolar_rod_spheres(g);
            break;
        }
        case BodyKind::bead:
            chain = bead_spheres({});
            break;
    }
    // A density relative to the polar rod's gives the mass through this body's own volume.
    const double mass = t.has("density") ? t.real("density") * polar_rod_density() *
                                               make_shape(chain, kPolarRodMass, name).volume
                                         : t.real("mass");
    return {name,
            kind,
            make_shape(chain, mass, name),
            {t.real("plate_friction"), t.real("plate_restitution")}};
}

}  // namespace rodsea::config
