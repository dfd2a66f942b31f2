#pragma once
// The key table: every key of the config file with its type, unit, default, allowed range,
// one-line description and, when docs/model.md marks its default a CHOICE, why. Parsing,
// validation, defaults, the resolved TOML and docs/config.md are all driven by it.
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "rodsea/config/config_values.hpp"
#include "rodsea/engine/parameters.hpp"

namespace rodsea::config {

enum class ValueType {
    real,       // TOML float or integer
    integer,    // TOML integer
    text,       // TOML string
    option,     // TOML string, one of KeySpec::options
    name_pair,  // TOML array of two strings
};

// Which kinds of body a [[species]] key applies to (a bit per BodyKind).
using KindMask = unsigned;
inline constexpr KindMask kPolarRod = 1u, kApolarRod = 2u, kBead = 4u,
                          kAllKinds = kPolarRod | kApolarRod | kBead;
KindMask kind_bit(BodyKind kind);

struct Interval {
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    bool lo_open = false;
    bool hi_open = false;
    bool contains(double v) const;
};

struct KeySpec {
    std::string table;  // schema path of its table: "drive", "species", "collisions.pair"
    std::string name;
    ValueType type = ValueType::real;
    std::string unit;                    // "" when dimensionless
    std::optional<Value> default_value;  // none: required, an alternative, or kind-dependent
    std::string default_text;            // the docs' default when default_value cannot say it
    std::optional<Value> example;        // shown, commented out, where a key has no value
    Interval range;                      // reals
    std::int64_t min_integer = 0;        // integers, inclusive
    std::int64_t max_integer = std::numeric_limits<std::int64_t>::max();
    std::vector<std::string> options;  // ValueType::option
    std::string doc;
    std::string choice;  // why docs/model.md makes the default a CHOICE; empty when it is not one
    KindMask choice_kinds = kAllKinds;  // [[species]] keys: the kinds for which it is a CHOICE
    std::string alternative;            // key of the same table it excludes
    KindMask kinds = kAllKinds;         // [[species]] keys: the kinds it applies to
    bool required = false;

    std::string path() const;          // "table.name", or the name of a key outside any table
    std::string type_text() const;     // "real", "integer", ...
    std::string allowed_text() const;  // "(0, 100000] mm", "\"isotropic\" or \"aligned\""
    std::string default_doc() const;   // the default as the docs show it
    std::string shown(const Value& v) const;  // a value as messages show it: "1.5 mm"
    bool is_choice_for(BodyKind kind) const {
        return !choice.empty() && (choice_kinds & kind_bit(kind));
    }
};

struct TableSpec {
    std::string path;    // "box", "collisions.pair"
    bool array = false;  // an array of tables ([[species]])
    std::string doc;
};

Interval closed(double lo, double hi);
Interval left_open(double lo, double hi);

// Fluent construction keeps each entry of a key table readable as one block:
//   real("drive", "gap").unit("mm").def(1.40).range(left_open(0.0, 100.0)).doc("...")
class Key {
  public:
    Key(std::string table, std::string name, ValueType type) {
        s_.table = std::move(table);
        s_.name = std::move(name);
        s_.type = type;
    }
    Key& unit(std::string u) { return s_.unit = std::move(u), *this; }
    Key& def(Value v) { return s_.default_value = std::move(v), *this; }
    Key& def_text(std::string t) { return s_.default_text = std::move(t), *this; }
    Key& example(Value v) { return s_.example = std::move(v), *this; }
    Key& range(Interval r) { return s_.range = r, *this; }
    Key& integers(std::int64_t lo, std::int64_t hi) {
        s_.min_integer = lo;
        s_.max_integer = hi;
        return *this;
    }
    Key& options(std::vector<std::string> o) { return s_.options = std::move(o), *this; }
    Key& doc(std::string d) { return s_.doc = std::move(d), *this; }
    Key& choice(std::string why, KindMask kinds = kAllKinds) {
        s_.choice = std::move(why);
        s_.choice_kinds = kinds;
        return *this;
    }
    Key& alternative(std::string key) { return s_.alternative = std::move(key), *this; }
    Key& kinds(KindMask k) { return s_.kinds = k, *this; }
    Key& required() { return s_.required = true, *this; }
    operator KeySpec() const { return s_; }

  private:
    KeySpec s_;
};
Key real(std::string table, std::string name);
Key integer(std::string table, std::string name);

// A number given as text (a command-line KEY=VALUE) checked against a real or integer key:
// throws InvalidParameter naming the key, the text and its allowed range.
Value value_from_text(const KeySpec& spec, const std::string& text);

const std::vector<TableSpec>& config_tables();  // in file order
const std::vector<KeySpec>& config_keys();      // in file order, grouped by table
const TableSpec* find_table(std::string_view path);
const KeySpec* find_key(std::string_view table, std::string_view name);
std::vector<const KeySpec*> keys_of(std::string_view table);

// Constants the keys refer to.
inline constexpr double kPolarRodLength = 4.5;  // ℓ_p, mm: the unit of box.side_in_polar_lengths
inline constexpr double kApolarRodDiameter = 0.8;   // mm: σ = ℓ_a / 0.8 mm
inline constexpr double kMaxAreaFraction = 0.9069;  // π/(2√3), hexagonal packing of discs

// Text for a cell of a Markdown table: a bare '|' would end the cell (|u_n| in the noise docs).
std::string markdown_cell(const std::string& text);

// A value as the docs show it: like TOML, but whole reals without ".0".
std::string doc_text(const Value& v);

// The default of a [[species]] key that depends on the kind (and, for the sphere count of an
// apolar rod, on its length); none when the key has no default for that kind.
std::optional<Value> species_default(std::string_view key, BodyKind kind, double length_mm);

}  // namespace rodsea::config
