#include "rodsea/config/campaign_file.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "rodsea/config/config_file.hpp"
#include "rodsea/config/detail/choices.hpp"
#include "rodsea/config/detail/read_toml.hpp"
#include "rodsea/config/detail/resolve.hpp"
#include "rodsea/config/detail/write_toml.hpp"
#include "rodsea/config/did_you_mean.hpp"
#include "rodsea/config/schema.hpp"
#include "rodsea/error.hpp"
#include "rodsea/number_text.hpp"

namespace rodsea {

namespace {

namespace fs = std::filesystem;
using config::Value;

// The campaign file's keys: what the reader accepts and what docs/campaigns.md lists.
struct CampaignKey {
    std::string table, name, type, unit, default_text, doc;
};
struct CampaignTable {
    std::string name;
    bool array = false;
    std::string doc;
};

const std::vector<CampaignTable>& campaign_tables() {
    static const std::vector<CampaignTable> tables{
        {"campaign", false, "What the campaign is and how many replicates each point gets."},
        {"base", false,
         "The base config inline, as any run config with its tables one level down "
         "([base.box], [[base.species]]; every key in docs/config.md). Excludes "
         "`campaign.base`. Relative paths in it (noise.calibration_table) are relative to the "
         "campaign file."},
        {"axis", true,
         "One axis of the grid; the points are the product of all axes. A key is written as "
         "in docs/config.md, with a [[species]] element named by its name: `box.side`, "
         "`noise.rotational_diffusion`, `species.medium.area_fraction`. Setting a key drops "
         "the key it excludes (an axis over `area_fraction` replaces a `count`)."},
        {"override", true,
         "Keys set at the points that match: e.g. a longer duration at the densest points."},
        {"analysis", false, "What `rodsea campaign collect` runs on every finished run."},
        {"figure", true,
         "A figure `collect` draws into collected/figures/. `kind = \"curve\"`: scalars of the "
         "collected table against an axis, one curve per value of `series`, error bars from "
         "the replicates. `\"map\"`: one scalar coloured over two axes (`x` and `series`), "
         "with a contour at `level` (a phase diagram). `\"analysis\"`: one of `rodsea plot`'s "
         "figures of each point's first replicate. `\"snapshot\"`: each point's final frame "
         "(`rodsea render`). `\"movie\"`: the points' first replicates side by side in one "
         "movie (`rodsea movie RUN1 RUN2 ...`). `when` picks the points."},
    };
    return tables;
}

const std::vector<CampaignKey>& campaign_keys() {
    static const std::vector<CampaignKey> keys{
        {"campaign", "name", "string", "", "the file's name", "Names the output directory."},
        {"campaign", "description", "string", "", "\"\"", "What the campaign reproduces."},
        {"campaign", "base", "string", "", "—",
         "A config file (relative to the campaign file) that every point starts from. "
         "Excludes a [base] table; without either, every point starts from the defaults."},
        {"campaign", "replicates", "integer", "", "1",
         "Runs per point, with seeds first_seed, first_seed + 1, ...: their spread gives the "
         "error bars of `collect`. In [1, 1000]."},
        {"campaign", "first_seed", "integer", "", "1",
         "The first replicate's run.seed (the base's run.seed is replaced). In [0, 2^62]."},
        {"axis", "key", "string", "", "—",
         "The config key this axis sets (not `run.seed`: replicates give the seeds). Excludes "
         "`keys`."},
        {"axis", "keys", "array of strings", "", "—",
         "Several keys set together (a zipped axis): `values` is then an array of arrays, one "
         "value per key. Never a key beside its alternative (`length` and `aspect_ratio`)."},
        {"axis", "values", "array", "the key's", "required",
         "The values, in the key's unit (docs/config.md); each is checked against the key's "
         "range before anything runs."},
        {"override", "when", "table", "", "{} (every point)",
         "Axis keys and values a point must have, e.g. `{ \"species.medium.area_fraction\" = "
         "0.8 }`."},
        {"override", "set", "table", "", "required",
         "Keys and values set at those points, e.g. `{ \"time.duration\" = 200.0 }`: not an "
         "axis key (a point is named by its axis values) nor `run.seed`, and no key that another "
         "override also sets at the same point."},
        {"analysis", "from", "real", "s", "automatic",
         "Start of the steady window of every run (`rodsea analyze --from`); without it each "
         "run's own automatic window (docs/analysis.md)."},
        {"analysis", "to", "real", "s", "the run's end",
         "End of the window of every run (`rodsea analyze --to`): each run analysed as if it "
         "had ended there, so runs of different lengths compare over one window. At least "
         "`from`, with a frame between them; at most every point's last frame; not with "
         "`time.steady_samples` (runs that stop when steady)."},
        {"analysis", "observables", "array of strings", "", "all that apply",
         "The observables to compute (`rodsea analyze --observables`)."},
        {"analysis", "parameters", "table", "", "{}",
         "Analysis parameters (`rodsea analyze --param`), e.g. `{ \"flocks.eps\" = 2.25 }`."},
        {"figure", "name", "string", "", "required",
         "The figure's file name, without extension (a folder of PNGs for analysis and "
         "snapshot, an .mp4 for movie)."},
        {"figure", "kind", "string", "", "\"curve\"",
         "One of curve, map, analysis, snapshot, movie."},
        {"figure", "x", "string", "", "required (curve, map)",
         "The axis key on the horizontal axis."},
        {"figure", "y", "array of strings", "", "required (curve, map)",
         "Scalars of the collected table (`P_polar`, `Sigma`, ...): on the vertical axis "
         "(curve), or the one coloured (map)."},
        {"figure", "series", "string", "", "\"\" (curve); required (map)",
         "An axis key. Curve: one curve per value (empty: one curve per y). Map: the vertical "
         "axis."},
        {"figure", "level", "real", "the scalar's", "none",
         "Map: the value whose contour is drawn, e.g. 0.5 for P = 0.5."},
        {"figure", "plot", "string", "", "required (analysis)",
         "Analysis: the figure of `rodsea plot` (g_r_theta, G_r_theta, autocorrelation, "
         "flock_sizes, flocks_time, order_parameters, pair_correlation, segregation, bands, "
         "medium_velocity)."},
        {"figure", "when", "table", "", "{} (every point)",
         "The points drawn: axis keys and a value or an array of values, e.g. "
         "`{ \"species.medium.area_fraction\" = [0.05, 0.80] }`."},
        {"figure", "xlabel", "string", "", "the key", "The horizontal axis' label."},
        {"figure", "ylabel", "string", "", "the scalars", "The vertical axis' label."},
        {"figure", "serieslabel", "string", "", "the series key",
         "Curve: the series' name in the legend, e.g. \"φ_p\" for curves labelled φ_p = 0.05."},
        {"figure", "title", "string", "", "\"\"", "The figure's title."},
        {"figure", "logx", "boolean", "", "false", "A logarithmic horizontal axis."},
        {"figure", "logy", "boolean", "", "false", "A logarithmic vertical axis."},
    };
    return keys;
}

long line_of(const toml::node& node) {
    return static_cast<long>(node.source().begin.line);
}

// Reads one campaign file, naming every problem by its key path and line.
class CampaignReader {
  public:
    CampaignReader(std::string source, fs::path directory)
        : source_(std::move(source)), directory_(std::move(directory)) {}

    Campaign read(const toml::table& root) {
        // A run config given where a campaign file belongs (examples/paper/'s base-*.toml sit
        // beside the campaigns that use them): say what it is, not that [box] is unknown here.
        if (!root.contains("campaign") && (root.contains("box") || root.contains("species") ||
                                           root.contains("drive") || root.contains("time")))
            throw InvalidParameter("campaign", source_, "a campaign file (with a [campaign] table)",
                                   "this is a run config: rodsea run it, or name it as a "
                                   "campaign's base (campaign.base, docs/campaigns.md)");
        Campaign c;
        c.file = source_;
        for (auto&& [k, node] : root) {
            const std::string name(k.str());
            const auto t = std::find_if(campaign_tables().begin(), campaign_tables().end(),
                                        [&](const CampaignTable& x) { return x.name == name; });
            if (t == campaign_tables().end()) {
                std::vector<std::string> names;
                for (const CampaignTable& x : campaign_tables())
                    names.push_back(x.name);
                unknown(name, name, names, node);
            }
        }
        if (const toml::table* campaign = table(root, "campaign")) read_campaign(*campaign, c);
        if (const toml::table* base = table(root, "base")) {
            if (!c.base_source.empty())
                throw InvalidParameter("base", "a table", "campaign.base or [base], not both",
                                       where(*base));
            c.base_toml = inline_base(*base);
            c.base_source = source_ + " [base]";
        }
        for (const toml::table* axis : tables(root, "axis"))
            c.axes.push_back(read_axis(*axis, "axis[" + std::to_string(c.axes.size()) + "]"));
        for (const toml::table* o : tables(root, "override"))
            c.overrides.push_back(
                read_override(*o, "override[" + std::to_string(c.overrides.size()) + "]"));
        if (const toml::table* a = table(root, "analysis")) c.analysis = read_analysis(*a);
        for (const toml::table* f : tables(root, "figure"))
            c.figures.push_back(
                read_figure(*f, "figure[" + std::to_string(c.figures.size()) + "]"));
        check_whole(c);
        return c;
    }

  private:
    std::string where(const toml::node& node) const {
        return source_ + " line " + std::to_string(line_of(node));
    }

    [[noreturn]] void unknown(const std::string& path, const std::string& key,
                              const std::vector<std::string>& allowed,
                              const toml::node& node) const {
        std::string list;
        for (const std::string& a : allowed)
            list += (list.empty() ? "" : ", ") + a;
        const auto guess = config::closest_match(key, allowed);
        throw InvalidParameter(
            path, "", "one of " + list,
            config::join_why(guess ? "unknown; did you mean '" + *guess + "'?" : "unknown",
                             where(node)));
    }

    // The keys of `t` must be keys of the campaign table `name`.
    void check_keys(const toml::table& t, const std::string& name, const std::string& path) const {
        std::vector<std::string> allowed;
        for (const CampaignKey& k : campaign_keys())
            if (k.table == name) allowed.push_back(k.name);
        for (auto&& [k, node] : t) {
            const std::string key(k.str());
            if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
                unknown(path + "." + key, key, allowed, node);
        }
    }

    const toml::table* table(const toml::table& root, const std::string& name) const {
        const toml::node* node = root.get(name);
        if (!node) return nullptr;
        if (!node->is_table())
            throw InvalidParameter(name, "not a table", "a table [" + name + "]", where(*node));
        return node->as_table();
    }

    std::vector<const toml::table*> tables(const toml::table& root, const std::string& name) const {
        std::vector<const toml::table*> out;
        const toml::node* node = root.get(name);
        if (!node) return out;
        const toml::array* array = node->as_array();
        if (!array)
            throw InvalidParameter(name, "not an array of tables", "[[" + name + "]] tables",
                                   where(*node));
        for (const toml::node& e : *array) {
            if (!e.is_table())
                throw InvalidParameter(name, "not a table", "[[" + name + "]] tables", where(e));
            out.push_back(e.as_table());
        }
        return out;
    }

    std::string text(const toml::table& t, const std::string& key, const std::string& path,
                     const std::string& fallback = "") const {
        const toml::node* node = t.get(key);
        if (!node) return fallback;
        const auto* s = node->as_string();
        if (!s) throw InvalidParameter(path + "." + key, "not a string", "a string", where(*node));
        return std::string(s->get());
    }

    std::int64_t integer(const toml::table& t, const std::string& key, const std::string& path,
                         std::int64_t fallback, std::int64_t lo, std::int64_t hi) const {
        const toml::node* node = t.get(key);
        if (!node) return fallback;
        const auto* i = node->as_integer();
        if (!i || i->get() < lo || i->get() > hi)
            throw InvalidParameter(
                path + "." + key, i ? std::to_string(i->get()) : "not an integer",
                "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]",
                where(*node));
        return i->get();
    }

    std::vector<std::string> strings(const toml::table& t, const std::string& key,
                                     const std::string& path) const {
        std::vector<std::string> out;
        const toml::node* node = t.get(key);
        if (!node) return out;
        const toml::array* a = node->as_array();
        const auto bad = [&](const toml::node& n) {
            throw InvalidParameter(path + "." + key, "not an array of strings",
                                   "an array of strings", where(n));
        };
        if (!a) bad(*node);
        for (const toml::node& e : *a) {
            if (!e.as_string()) bad(e);
            out.emplace_back(e.as_string()->get());
        }
        return out;
    }

    Value value(const toml::node& node, const std::string& path) const {
        if (const auto* f = node.as_floating_point()) return f->get();
        if (const auto* i = node.as_integer()) return i->get();
        if (const auto* s = node.as_string()) return std::string(s->get());
        throw InvalidParameter(path, "not a number or a string",
                               "a number or a string, as the key takes", where(node));
    }

    std::vector<KeySetting> settings(const toml::table& t, const std::string& path) const {
        std::vector<KeySetting> out;
        for (auto&& [k, node] : t) {
            const std::string key(k.str());
            if (node.is_table())
                throw InvalidParameter(
                    path + "." + key, "a table",
                    "keys in quotes with their dots: { \"" + key + ".name\" = ... }", where(node));
            const Value v = value(node, path + "." + key);
            check_key_setting(key, v, path, where(node));
            out.emplace_back(key, v);
        }
        return out;
    }

    void read_campaign(const toml::table& t, Campaign& c) const {
        check_keys(t, "campaign", "campaign");
        c.name = text(t, "name", "campaign");
        const bool safe_name = c.name.size() <= 100 && c.name != "." && c.name != ".." &&
                               std::all_of(c.name.begin(), c.name.end(), [](char ch) {
                                   return std::isalnum(static_cast<unsigned char>(ch)) ||
                                          ch == '_' || ch == '-' || ch == '.';
                               });
        if (t.contains("name") && (c.name.empty() || !safe_name))
            throw InvalidParameter("campaign.name", config::toml_literal(c.name),
                                   "1 to 100 letters, digits, '_', '-' or '.' (it names the "
                                   "output directory and the cluster's jobs)",
                                   where(*t.get("name")));
        c.description = text(t, "description", "campaign");
        c.replicates = static_cast<int>(integer(t, "replicates", "campaign", 1, 1, 1000));
        c.first_seed = static_cast<std::uint64_t>(
            integer(t, "first_seed", "campaign", 1, 0, std::int64_t{1} << 62));
        const std::string base = text(t, "base", "campaign");
        if (!base.empty()) {
            fs::path path = base;
            if (path.is_relative()) path = directory_ / path;
            std::ifstream in(path, std::ios::binary);
            if (!in || fs::is_directory(path))
                throw FileError(path.string(), "the campaign's base config (campaign.base in " +
                                                   source_ + ") cannot be read");
            std::ostringstream s;
            s << in.rdbuf();
            c.base_toml = s.str();
            c.base_source = path.lexically_normal().string();
        }
    }

    // The [base] table as a config of its own; a relative calibration table is made relative
    // to the campaign file, where the user wrote it.
    std::string inline_base(const toml::table& base) const {
        toml::table copy = base;
        if (toml::table* noise = copy["noise"].as_table())
            if (const auto* table = noise->get_as<std::string>("calibration_table")) {
                fs::path p = table->get();
                if (p.is_relative())
                    noise->insert_or_assign("calibration_table",
                                            fs::absolute(directory_ / p).string());
            }
        std::ostringstream s;
        s << copy;
        return s.str();
    }

    CampaignAxis read_axis(const toml::table& t, const std::string& path) const {
        check_keys(t, "axis", path);
        CampaignAxis axis;
        const bool one = t.contains("key"), many = t.contains("keys");
        if (one == many)
            throw InvalidParameter(path, one ? "key and keys" : "neither key nor keys",
                                   "exactly one of key (one key) or keys (a zipped axis)",
                                   where(t));
        axis.keys = one ? std::vector<std::string>{text(t, "key", path)} : strings(t, "keys", path);
        if (axis.keys.empty())
            throw InvalidParameter(path + ".keys", "[]", "at least one key", where(t));
        const toml::array* values = t.get_as<toml::array>("values");
        if (!values || values->empty())
            throw InvalidParameter(path + ".values", values ? "[]" : "missing",
                                   "a non-empty array of values", where(t));
        for (std::size_t i = 0; i < values->size(); ++i) {
            const toml::node& v = *values->get(i);
            const std::string vpath = path + ".values[" + std::to_string(i) + "]";
            std::vector<Value> tuple;
            if (many) {
                const toml::array* a = v.as_array();
                if (!a || a->size() != axis.keys.size())
                    throw InvalidParameter(
                        vpath, a ? std::to_string(a->size()) + " values" : "not an array",
                        "an array of " + std::to_string(axis.keys.size()) + " values, one per key",
                        where(v));
                for (const toml::node& e : *a)
                    tuple.push_back(value(e, vpath));
            } else {
                tuple.push_back(value(v, vpath));
            }
            for (std::size_t k = 0; k < tuple.size(); ++k)
                check_key_setting(axis.keys[k], tuple[k], vpath, where(v));
            if (std::find(axis.values.begin(), axis.values.end(), tuple) != axis.values.end())
                throw InvalidParameter(vpath, setting_text(tuple.front()), "each value once",
                                       where(v));
            axis.values.push_back(std::move(tuple));
        }
        return axis;
    }

    CampaignOverride read_override(const toml::table& t, const std::string& path) const {
        check_keys(t, "override", path);
        CampaignOverride o;
        if (const toml::node* when = t.get("when")) {
            if (!when->is_table())
                throw InvalidParameter(path + ".when", "not a table", "an inline table",
                                       where(*when));
            o.when = settings(*when->as_table(), path + ".when");
        }
        const toml::node* set = t.get("set");
        if (!set || !set->is_table())
            throw InvalidParameter(path + ".set", set ? "not a table" : "missing",
                                   "an inline table of keys and values", where(t));
        o.set = settings(*set->as_table(), path + ".set");
        return o;
    }

    CampaignAnalysis read_analysis(const toml::table& t) const {
        check_keys(t, "analysis", "analysis");
        CampaignAnalysis a;
        if (const toml::node* from = t.get("from")) {
            const auto v = from->value<double>();
            if (!v || !std::isfinite(*v) || *v < 0.0)
                throw InvalidParameter("analysis.from", "", "a time >= 0 s", where(*from));
            a.from = *v;
        }
        if (const toml::node* to = t.get("to")) {
            const auto v = to->value<double>();
            const double lowest = a.from.value_or(0.0);
            if (!v || !std::isfinite(*v) || *v < lowest)
                throw InvalidParameter(
                    "analysis.to", v ? format_number(*v) + " s" : "",
                    a.from ? "at least analysis.from (" + format_number(lowest) + " s)"
                           : "a time >= 0 s",
                    where(*to));
            a.to = *v;
        }
        a.observables = strings(t, "observables", "analysis");
        if (const toml::node* p = t.get("parameters")) {
            if (!p->is_table())
                throw InvalidParameter("analysis.parameters", "not a table", "an inline table",
                                       where(*p));
            for (auto&& [k, node] : *p->as_table()) {
                const Value v = value(node, campaign_analysis_parameter_name(std::string(k.str())));
                a.parameters.emplace_back(std::string(k.str()), setting_text(v));
            }
        }
        return a;
    }

    CampaignFigure read_figure(const toml::table& t, const std::string& path) const {
        check_keys(t, "figure", path);
        CampaignFigure f;
        f.name = text(t, "name", path);
        const std::string kind = text(t, "kind", path, "curve");
        const std::vector<std::string> kinds{"curve", "map", "analysis", "snapshot", "movie"};
        const auto k = std::find(kinds.begin(), kinds.end(), kind);
        if (k == kinds.end()) {
            const auto guess = config::closest_match(kind, kinds);
            throw InvalidParameter(
                path + ".kind", config::toml_literal(kind),
                "curve, map, analysis, snapshot or movie",
                config::join_why(guess ? "did you mean '" + *guess + "'?" : "", where(t)));
        }
        f.kind = static_cast<FigureKind>(k - kinds.begin());
        f.x = text(t, "x", path);
        f.y = strings(t, "y", path);
        f.series = text(t, "series", path);
        f.plot = text(t, "plot", path);
        f.xlabel = text(t, "xlabel", path);
        f.ylabel = text(t, "ylabel", path);
        f.series_label = text(t, "serieslabel", path);
        f.title = text(t, "title", path);
        for (const char* flag : {"logx", "logy"})
            if (const toml::node* n = t.get(flag)) {
                if (!n->is_boolean())
                    throw InvalidParameter(path + "." + flag, "not a boolean", "true or false",
                                           where(*n));
                (std::string(flag) == "logx" ? f.logx : f.logy) = n->as_boolean()->get();
            }
        if (const toml::node* n = t.get("level")) {
            const auto v = n->value<double>();
            if (!v || !std::isfinite(*v)) {
                const std::string given =
                    n->is_string() ? config::toml_literal(std::string(n->as_string()->get()))
                    : v            ? std::to_string(*v)
                                   : "not a number";
                throw InvalidParameter(path + ".level", given, "a finite number", where(*n));
            }
            f.level = *v;
        }
        if (const toml::node* when = t.get("when")) {
            if (!when->is_table())
                throw InvalidParameter(path + ".when", "not a table", "an inline table",
                                       where(*when));
            for (auto&& [key, node] : *when->as_table()) {
                const std::string wpath = path + ".when." + std::string(key.str());
                if (node.is_table())
                    throw InvalidParameter(wpath, "a table",
                                           "keys in quotes with their dots: { \"" +
                                               std::string(key.str()) + ".name\" = ... }",
                                           where(node));
                std::vector<Value> values;
                if (const toml::array* a = node.as_array())
                    for (const toml::node& e : *a)
                        values.push_back(value(e, wpath));
                else
                    values.push_back(value(node, wpath));
                if (values.empty())
                    throw InvalidParameter(wpath, "[]", "a value or a non-empty array",
                                           where(node));
                f.when.emplace_back(std::string(key.str()), std::move(values));
            }
        }
        const bool safe_name = !f.name.empty() && f.name.size() <= 100 &&
                               std::all_of(f.name.begin(), f.name.end(), [](char ch) {
                                   return std::isalnum(static_cast<unsigned char>(ch)) ||
                                          ch == '_' || ch == '-' || ch == '.';
                               });
        if (!safe_name)
            throw InvalidParameter(path + ".name", config::toml_literal(f.name),
                                   "1 to 100 letters, digits, '_', '-' or '.'", where(t));
        const bool table_figure = f.kind == FigureKind::curve || f.kind == FigureKind::map;
        const auto unused = [&](const char* key, bool given) {
            if (given)
                throw InvalidParameter(
                    path + "." + key, "given",
                    std::string("no ") + key + " for kind " + config::toml_literal(kind), where(t));
        };
        if (table_figure) {
            if (f.x.empty())
                throw InvalidParameter(path + ".x", "missing", "an axis key", where(t));
            if (f.y.empty())
                throw InvalidParameter(path + ".y", "missing", "one or more scalar names",
                                       where(t));
            unused("plot", !f.plot.empty());
        } else {
            unused("x", !f.x.empty());
            unused("y", !f.y.empty());
            unused("series", !f.series.empty());
            unused("serieslabel", !f.series_label.empty());
            unused("logx", t.contains("logx"));
            unused("logy", t.contains("logy"));
            unused("xlabel", !f.xlabel.empty());
            unused("ylabel", !f.ylabel.empty());
            unused("title", !f.title.empty());
        }
        if (f.kind == FigureKind::map) {
            if (f.series.empty())
                throw InvalidParameter(path + ".series", "missing",
                                       "the axis key of the map's vertical axis", where(t));
            if (f.y.size() != 1)
                throw InvalidParameter(path + ".y", std::to_string(f.y.size()) + " scalars",
                                       "the one scalar a map colours", where(t));
        } else {
            unused("level", f.level.has_value());
        }
        if (f.kind == FigureKind::analysis) {
            const std::vector<std::string> plots{
                "g_r_theta",   "G_r_theta",        "autocorrelation",  "flock_sizes",
                "flocks_time", "order_parameters", "pair_correlation", "segregation",
                "bands",       "medium_velocity"};
            if (std::find(plots.begin(), plots.end(), f.plot) == plots.end()) {
                std::string list;
                for (const std::string& p : plots)
                    list += (list.empty() ? "" : ", ") + p;
                const auto guess = config::closest_match(f.plot, plots);
                throw InvalidParameter(
                    path + ".plot", f.plot.empty() ? "missing" : config::toml_literal(f.plot),
                    "one of " + list,
                    config::join_why(guess ? "did you mean '" + *guess + "'?" : "", where(t)));
            }
        } else if (!table_figure) {
            unused("plot", !f.plot.empty());
        }
        return f;
    }

    // Checks that need the whole file: figure axes are axes, override conditions are axes.
    void check_whole(const Campaign& c) const {
        std::vector<std::string> axis_keys;
        for (const CampaignAxis& a : c.axes)
            for (const std::string& k : a.keys) {
                if (std::find(axis_keys.begin(), axis_keys.end(), k) != axis_keys.end())
                    throw InvalidParameter("axis", k, "each key on one axis only",
                                           "it is on two axes of " + source_);
                axis_keys.push_back(k);
            }
        const auto must_be_axis = [&](const std::string& key, const std::string& path) {
            if (std::find(axis_keys.begin(), axis_keys.end(), key) != axis_keys.end()) return;
            std::string list;
            for (const std::string& k : axis_keys)
                list += (list.empty() ? "" : ", ") + k;
            const auto guess = config::closest_match(key, axis_keys);
            throw InvalidParameter(
                path, key,
                list.empty() ? "an axis key (there are no axes)" : "an axis key: " + list,
                guess ? "did you mean '" + *guess + "'?" : source_);
        };
        // The seeds are the replicates': an axis or override over run.seed would give several
        // points one seed, or the replicates of one point the same.
        const std::string seeds_are_replicates =
            "campaign.replicates and campaign.first_seed give each point its seeds "
            "(first_seed, first_seed + 1, ...)";
        if (std::find(axis_keys.begin(), axis_keys.end(), "run.seed") != axis_keys.end())
            throw InvalidParameter("axis", "run.seed", "a config key other than run.seed",
                                   seeds_are_replicates);
        for (std::size_t i = 0; i < c.overrides.size(); ++i) {
            const std::string path = "override[" + std::to_string(i) + "]";
            for (const KeySetting& w : c.overrides[i].when)
                must_be_axis(w.first, path + ".when");
            for (const KeySetting& s : c.overrides[i].set) {
                if (s.first == "run.seed")
                    throw InvalidParameter(path + ".set", "run.seed",
                                           "a config key other than run.seed",
                                           seeds_are_replicates);
                if (std::find(axis_keys.begin(), axis_keys.end(), s.first) != axis_keys.end())
                    throw InvalidParameter(path + ".set", s.first, "a key no axis sets",
                                           "a point is named by its axis values; an override "
                                           "that changed one would run another point");
            }
        }
        for (std::size_t i = 0; i < c.figures.size(); ++i) {
            const CampaignFigure& f = c.figures[i];
            const std::string path = "figure[" + std::to_string(i) + "]";
            if (!f.x.empty()) must_be_axis(f.x, path + ".x");
            if (!f.series.empty()) must_be_axis(f.series, path + ".series");
            for (const auto& [key, values] : f.when) {
                must_be_axis(key, path + ".when");
                const CampaignAxis& axis =
                    *std::find_if(c.axes.begin(), c.axes.end(), [&](const CampaignAxis& a) {
                        return std::find(a.keys.begin(), a.keys.end(), key) != a.keys.end();
                    });
                const std::size_t k =
                    std::find(axis.keys.begin(), axis.keys.end(), key) - axis.keys.begin();
                for (const Value& v : values)
                    if (std::none_of(axis.values.begin(), axis.values.end(),
                                     [&](const std::vector<Value>& tuple) {
                                         return setting_text(tuple[k]) == setting_text(v);
                                     })) {
                        std::string list;
                        for (const std::vector<Value>& tuple : axis.values)
                            list += (list.empty() ? "" : ", ") + setting_text(tuple[k]);
                        throw InvalidParameter(path + ".when." + key, setting_text(v),
                                               "a value of the axis: " + list, source_);
                    }
            }
            for (std::size_t j = 0; j < i; ++j)
                if (c.figures[j].name == f.name)
                    throw InvalidParameter(path + ".name", f.name, "a name no other figure has",
                                           source_);
        }
    }

    std::string source_;
    fs::path directory_;
};

// "species.medium.area_fraction" → ("species", "medium", "area_fraction"); ("box", "", "side").
struct KeyPath {
    std::string table, species, key;
};

KeyPath split_key(const std::string& key, const std::string& where, const std::string& at = "") {
    KeyPath p;
    const std::size_t dot = key.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == key.size())
        throw InvalidParameter(where, key, "a config key TABLE.KEY, or species.NAME.KEY",
                               config::join_why("see docs/config.md", at));
    p.table = key.substr(0, dot);
    std::string rest = key.substr(dot + 1);
    if (p.table == "species") {
        const std::size_t second = rest.find('.');
        if (second == std::string::npos || second == 0 || second + 1 == rest.size())
            throw InvalidParameter(where, key, "species.NAME.KEY, NAME a [[species]] name",
                                   config::join_why("e.g. species.medium.area_fraction", at));
        p.species = rest.substr(0, second);
        rest = rest.substr(second + 1);
    }
    p.key = rest;
    return p;
}

const config::KeySpec& key_spec(const KeyPath& p, const std::string& full, const std::string& where,
                                const std::string& at = "") {
    const config::TableSpec* table = config::find_table(p.table);
    if (!table || (table->array && p.table != "species")) {
        std::vector<std::string> names;
        for (const config::TableSpec& t : config::config_tables())
            if (!t.array || t.path == "species") names.push_back(t.path);
        const auto guess = config::closest_match(p.table, names);
        throw InvalidParameter(
            where, full, "a key of a config table (docs/config.md)",
            config::join_why(guess ? "no table '" + p.table + "'; did you mean '" + *guess + "'?"
                                   : "no table '" + p.table + "' an axis can set",
                             at));
    }
    if (const config::KeySpec* spec = config::find_key(p.table, p.key)) return *spec;
    std::vector<std::string> names;
    for (const config::KeySpec* k : config::keys_of(p.table))
        names.push_back(k->name);
    const auto guess = config::closest_match(p.key, names);
    throw InvalidParameter(
        where, full, "a key of [" + p.table + "] (docs/config.md)",
        config::join_why(guess ? "did you mean '" + *guess + "'?" : "unknown key", at));
}

// The value as the key takes it: integers are fine where reals are expected.
Value checked_value(const config::KeySpec& spec, const Value& v, const std::string& full,
                    const std::string& where, const std::string& at = "") {
    const auto refuse = [&](const std::string& why) {
        throw InvalidParameter(where, full + " = " + setting_text(v), spec.allowed_text(),
                               config::join_why(why, at));
    };
    switch (spec.type) {
        case config::ValueType::real: {
            double x = 0.0;
            if (const auto* d = std::get_if<double>(&v))
                x = *d;
            else if (const auto* i = std::get_if<std::int64_t>(&v))
                x = static_cast<double>(*i);
            else
                refuse("not a number");
            if (!spec.range.contains(x)) refuse("out of range");
            return x;
        }
        case config::ValueType::integer: {
            const auto* i = std::get_if<std::int64_t>(&v);
            if (!i) refuse("not an integer");
            if (*i < spec.min_integer || *i > spec.max_integer) refuse("out of range");
            return *i;
        }
        case config::ValueType::text:
        case config::ValueType::option: {
            const auto* s = std::get_if<std::string>(&v);
            if (!s) refuse("not a string");
            if (spec.type == config::ValueType::option &&
                std::find(spec.options.begin(), spec.options.end(), *s) == spec.options.end()) {
                const auto guess = config::closest_match(*s, spec.options);
                refuse(guess ? "did you mean \"" + *guess + "\"?" : "not one of the options");
            }
            return v;
        }
        case config::ValueType::name_pair:
            refuse("a pair of names cannot be an axis");
    }
    return v;
}

}  // namespace

std::string setting_text(const Value& v) {
    if (const auto* d = std::get_if<double>(&v)) return exact_number(*d);
    if (const auto* i = std::get_if<std::int64_t>(&v)) return std::to_string(*i);
    if (const auto* s = std::get_if<std::string>(&v)) return *s;
    return config::toml_literal(v);
}

void check_key_setting(const std::string& key, const Value& value, const std::string& where,
                       const std::string& at) {
    const KeyPath p = split_key(key, where, at);
    checked_value(key_spec(p, key, where, at), value, key, where, at);
    if (p.table == "species" && (p.key == "name" || p.key == "kind"))
        throw InvalidParameter(
            where, key, "a key other than name and kind",
            config::join_why("a species keeps its name and kind across a campaign", at));
}

Campaign load_campaign_string(std::string_view toml, std::string_view source_name,
                              const fs::path& directory) {
    toml::table root;
    try {
        root = toml::parse(toml, source_name);
    } catch (const toml::parse_error& e) {
        throw ConfigSyntaxError(std::string(source_name), static_cast<long>(e.source().begin.line),
                                static_cast<long>(e.source().begin.column),
                                std::string(e.description()));
    }
    return CampaignReader(std::string(source_name), directory).read(root);
}

Campaign load_campaign_file(const fs::path& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw FileError(path.string(), "no such file");
    if (fs::is_directory(path, ec))
        throw FileError(path.string(), "is a directory, not a campaign file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError(path.string(), "cannot be opened for reading");
    std::ostringstream text;
    text << in.rdbuf();
    Campaign c = load_campaign_string(text.str(), path.string(), path.parent_path());
    c.file = path;
    if (c.name.empty()) c.name = path.stem().string();
    return c;
}

RunPlan config_with_settings(const std::string& base_toml, const std::string& base_source,
                             const std::vector<KeySetting>& settings, const std::string& what,
                             const CampaignScaling& scaling, const EpsilonLookup& epsilon) {
    config::ConfigValues values = config::read_toml(base_toml, base_source);
    std::vector<config::TableValues>& species = values.all("species");
    if (species.empty()) species = config::default_species();
    const auto table_for = [&](const KeyPath& p, const std::string& key) -> config::TableValues& {
        if (p.table != "species") {
            std::vector<config::TableValues>& t = values.all(p.table);
            if (t.empty()) t.push_back({p.table, 0, {}});
            return t.front();
        }
        std::string names;
        for (config::TableValues& s : species) {
            if (s.has("name") && s.text("name") == p.species) return s;
            names += (names.empty() ? "" : ", ") + (s.has("name") ? s.text("name") : "?");
        }
        throw InvalidParameter(what, key, "a species of the base config: " + names,
                               "no [[species]] named '" + p.species + "' in " + base_source);
    };
    const auto set = [&](const std::string& key, const Value& v) {
        const KeyPath p = split_key(key, what);
        const config::KeySpec& spec = key_spec(p, key, what);
        config::TableValues& t = table_for(p, key);
        t.entries[p.key] = {checked_value(spec, v, key, what), 0};
        if (!spec.alternative.empty()) t.entries.erase(spec.alternative);
    };
    // A point runs what its name says: each key is set once (an override or a second setting
    // of an axis key would replace the coordinate the point is named by), and never beside its
    // alternative (length and aspect_ratio), which a single config refuses as well.
    std::vector<std::string> set_keys;
    for (const KeySetting& s : settings) {
        const KeyPath p = split_key(s.first, what);
        const std::string table = p.table == "species" ? "species." + p.species : p.table;
        const config::KeySpec& spec = key_spec(p, s.first, what);
        const auto was_set = [&](const std::string& key) {
            return std::find(set_keys.begin(), set_keys.end(), table + "." + key) != set_keys.end();
        };
        if (was_set(p.key))
            throw InvalidParameter(what, s.first + " set twice", "each key once per point",
                                   "an override sets a key its point is named by");
        if (!spec.alternative.empty() && was_set(spec.alternative))
            throw InvalidParameter(what, s.first + " and " + table + "." + spec.alternative,
                                   "one of them", "a config gives exactly one of the two");
        set_keys.push_back(table + "." + p.key);
    }
    for (const KeySetting& s : settings)
        set(s.first, s.second);
    try {
        if (scaling.scale != 1.0) {
            // The side the settings give, then F times it; counts keep their density.
            config::ConfigValues probe = values;
            const RunPlan unscaled = config::resolve(probe, epsilon);
            set("box.side", unscaled.engine.box.lx * scaling.scale);
            for (config::TableValues& s : species)
                if (s.has("count"))
                    s.entries["count"] = {
                        std::max<std::int64_t>(
                            1, std::llround(static_cast<double>(s.integer("count")) *
                                            scaling.scale * scaling.scale)),
                        0};
        }
        if (scaling.duration) set("time.duration", *scaling.duration);
        RunPlan plan = config::resolve(values, epsilon);
        plan.config_toml = config::write_toml(values);
        plan.choices = config::list_choices(values, plan);
        return plan;
    } catch (const InvalidParameter& e) {
        throw e.in_context(what);
    }
}

const char* to_string(FigureKind kind) {
    switch (kind) {
        case FigureKind::curve:
            return "curve";
        case FigureKind::map:
            return "map";
        case FigureKind::analysis:
            return "analysis";
        case FigureKind::snapshot:
            return "snapshot";
        case FigureKind::movie:
            return "movie";
    }
    return "?";
}

std::string campaign_reference_markdown() {
    std::ostringstream md;
    md << "<!-- Generated from the campaign key table (src/rodsea/config/campaign_file.cpp) by "
          "campaign_reference_markdown(): regenerate with `rodsea campaign --reference`. -->\n";
    for (const CampaignTable& t : campaign_tables()) {
        md << "\n### " << (t.array ? "[[" + t.name + "]]" : "[" + t.name + "]") << "\n\n"
           << t.doc << "\n";
        bool header = false;
        for (const CampaignKey& k : campaign_keys()) {
            if (k.table != t.name) continue;
            if (!header) {
                md << "\n| key | type | unit | default | description |\n|---|---|---|---|---|\n";
                header = true;
            }
            md << "| `" << k.name << "` | " << k.type << " | "
               << config::markdown_cell(k.unit.empty() ? "—" : k.unit) << " | "
               << config::markdown_cell(k.default_text) << " | " << config::markdown_cell(k.doc)
               << " |\n";
        }
    }
    return md.str();
}

}  // namespace rodsea
