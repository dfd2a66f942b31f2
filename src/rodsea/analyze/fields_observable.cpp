#include "rodsea/analyze/fields_observable.hpp"

#include <cmath>
#include <limits>

#include "rodsea/analysis/contour_length.hpp"
#include "rodsea/error.hpp"

namespace rodsea {

namespace {

// What a kept time series of maps may take in memory (single precision) before the analysis
// asks for a coarser fields.every: a paper-size run (56 × 56 cells, 12 maps, 1000 frames) takes
// 150 MB.
constexpr double kMaxSeriesBytes = 2e9;

struct FieldSpec {
    const char* field;
    const char* unit;
    const char* description;
    std::vector<double> GroupFields::*values;
    bool weighted;
};

std::vector<FieldSpec> fields_of(BodyKind kind) {
    std::vector<FieldSpec> f{
        {"area_fraction", "", "area fraction (projected area per cell area)",
         &GroupFields::area_fraction, false},
        {"vx", "mm/s", "mean in-plane velocity, x", &GroupFields::vx, true},
        {"vy", "mm/s", "mean in-plane velocity, y", &GroupFields::vy, true},
    };
    if (kind == BodyKind::polar_rod) {
        f.push_back({"px", "", "polarisation: mean cos θ of the axes (thick → thin)",
                     &GroupFields::px, true});
        f.push_back({"py", "", "polarisation: mean sin θ", &GroupFields::py, true});
    }
    if (kind != BodyKind::bead) {
        f.push_back({"qxx", "", "nematic tensor: mean cos 2θ (S = |Q|, director ½ arg Q)",
                     &GroupFields::qxx, true});
        f.push_back({"qxy", "", "nematic tensor: mean sin 2θ", &GroupFields::qxy, true});
    }
    return f;
}

std::size_t map_count(const AnalysisSetup& setup) {
    std::size_t n = 0;
    for (const SpeciesInfo& s : setup.species)
        n += fields_of(s.kind).size();
    return n;
}

std::vector<std::uint64_t> dims_of(const FieldGrid& g) {
    return {static_cast<std::uint64_t>(g.ny), static_cast<std::uint64_t>(g.nx)};
}

}  // namespace

void check_field_series_memory(const AnalysisSetup& setup, const AnalysisOptions& options) {
    const FieldGrid grid = FieldGrid::of(setup.box, options.field_cell);
    const double kept = std::ceil(static_cast<double>(setup.frames) / options.field_every);
    const double bytes =
        kept * static_cast<double>(grid.cells() * map_count(setup)) * sizeof(float);
    if (bytes <= kMaxSeriesBytes) return;
    const double every =
        std::ceil(static_cast<double>(options.field_every) * bytes / kMaxSeriesBytes);
    throw InvalidParameter("fields.every", std::to_string(options.field_every),
                           "at least " + format_number(every) + " for this run",
                           "the maps of " + format_number(kept) + " frames (" +
                               std::to_string(grid.nx) + " × " + std::to_string(grid.ny) +
                               " cells, " + std::to_string(map_count(setup)) +
                               " maps) would take " + format_number(std::round(bytes / 1e6)) +
                               " MB, over the " + format_number(kMaxSeriesBytes / 1e6) +
                               " MB an analysis holds; or a larger fields.cell");
}

FieldsObservable::FieldsObservable(const AnalysisSetup& setup, const AnalysisOptions& options)
    : setup_(setup),
      cell_(options.field_cell),
      every_(options.field_every),
      level_(options.interface_level),
      grid_(FieldGrid::of(setup.box, options.field_cell)) {
    for (std::uint32_t s = 0; s < setup.species.size(); ++s)
        for (const FieldSpec& f : fields_of(setup.species[s].kind))
            maps_.push_back({s,
                             f.field,
                             f.unit,
                             f.description,
                             f.values,
                             f.weighted,
                             {},
                             std::vector<double>(grid_.cells(), 0.0),
                             std::vector<double>(grid_.cells(), 0.0)});
    interface_ = setup.polar_count() > 0 && setup.total_count() > setup.polar_count();
}

void FieldsObservable::compute(const FrameContext& context) {
    const FrameFields& fields = context.fields(cell_);
    const bool keep = frames_seen_ % static_cast<std::size_t>(every_) == 0;
    ++frames_seen_;
    if (keep) {
        kept_times_.push_back(context.frame().time);
        kept_steady_.push_back(context.steady() ? 1 : 0);
    }
    if (context.steady()) ++steady_frames_;
    for (Map& m : maps_) {
        const GroupFields& f = fields.species[m.species];
        for (std::size_t c = 0; c < grid_.cells(); ++c) {
            const double v = (f.*m.values)[c];
            if (keep) m.series.push_back(static_cast<float>(v));
            if (!context.steady()) continue;
            const double w = m.weighted ? f.weight[c] : 1.0;
            if (w > 0.0) {
                m.sum[c] += w * v;
                m.weight[c] += w;
            }
        }
    }
    if (!interface_) return;
    // The polar rods' share of the local area fraction; an empty cell is not polar-rich.
    std::vector<double> polar(grid_.cells(), 0.0), all(grid_.cells(), 0.0);
    for (std::uint32_t s = 0; s < setup_.species.size(); ++s)
        for (std::size_t c = 0; c < grid_.cells(); ++c) {
            const double phi = fields.species[s].area_fraction[c];
            all[c] += phi;
            if (setup_.species[s].kind == BodyKind::polar_rod) polar[c] += phi;
        }
    for (std::size_t c = 0; c < grid_.cells(); ++c)
        polar[c] = all[c] > 0.0 ? polar[c] / all[c] : 0.0;
    const LevelSet interface = level_set(grid_, polar, level_);
    times_.push_back(context.frame().time);
    steady_.push_back(context.steady() ? 1 : 0);
    length_.push_back(interface.length);
    rich_.push_back(interface.above_fraction);
}

ObservableResults FieldsObservable::finish() {
    ObservableResults r;
    r.observable = name();
    r.parameters = {{"cell_x", grid_.dx, "mm"},
                    {"cell_y", grid_.dy, "mm"},
                    {"nx", static_cast<double>(grid_.nx), ""},
                    {"ny", static_cast<double>(grid_.ny), ""},
                    {"every", static_cast<double>(every_), ""},
                    {"interface_level", level_, ""}};
    std::vector<double> x, y;
    for (int i = 0; i < grid_.nx; ++i)
        x.push_back((i + 0.5) * grid_.dx);
    for (int j = 0; j < grid_.ny; ++j)
        y.push_back((j + 0.5) * grid_.dy);
    const auto n = static_cast<std::uint64_t>(kept_times_.size());
    r.datasets.push_back({"fields/x", "cell centres along x", "mm", {x.size()}, x});
    r.datasets.push_back({"fields/y", "cell centres along y", "mm", {y.size()}, y});
    r.datasets.push_back(
        {"fields/time", "time of each kept map (fields.every)", "s", {n}, kept_times_});
    r.datasets.push_back({"fields/steady",
                          "1 where the kept map is inside the steady window",
                          "",
                          {n},
                          kept_steady_});
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<std::uint64_t> d = dims_of(grid_);
    std::vector<std::vector<double>> means;
    for (const Map& m : maps_) {
        means.emplace_back(grid_.cells(), nan);
        for (std::size_t c = 0; c < grid_.cells(); ++c)
            if (m.weight[c] > 0.0) means.back()[c] = m.sum[c] / m.weight[c];
    }
    for (std::size_t k = 0; k < maps_.size(); ++k) {
        Map& m = maps_[k];
        const std::string species = setup_.species[m.species].name;
        r.datasets.push_back({"fields/series/" + species + "/" + m.field,
                              m.description + ", per kept frame [frame][y][x]; NaN: no body",
                              m.unit,
                              {n, d[0], d[1]},
                              std::move(m.series)});
        r.datasets.push_back({"fields/mean/" + species + "/" + m.field,
                              m.description + ", steady-window average [y][x]" +
                                  (m.weighted ? " weighted by each frame's bodies per cell" : ""),
                              m.unit, d, means[k]});
        // Beside Q's components, the order and director of the averaged Q (fields_of() lists
        // qxy right after qxx).
        if (m.field != "qxy") continue;
        const std::vector<double>&qxx = means[k - 1], &qxy = means[k];
        std::vector<double> order(grid_.cells()), director(grid_.cells());
        for (std::size_t c = 0; c < grid_.cells(); ++c) {
            order[c] = std::hypot(qxx[c], qxy[c]);
            director[c] = 0.5 * std::atan2(qxy[c], qxx[c]);
        }
        r.datasets.push_back({"fields/mean/" + species + "/S",
                              "nematic order |⟨Q⟩| of the steady-window average [y][x]", "", d,
                              std::move(order)});
        r.datasets.push_back({"fields/mean/" + species + "/director",
                              "director ½ arg ⟨Q⟩ of the steady-window average [y][x]", "rad", d,
                              std::move(director)});
    }
    if (interface_) {
        const double area = setup_.box.lx * setup_.box.ly;
        TableResult t{"interface",
                      "the level line where the polar rods' share of the local area fraction "
                      "crosses fields.interface_level: its length, that length per box area, and "
                      "the polar-rich fraction of the box, every frame",
                      {"time", "steady", "length", "length_per_area", "polar_rich_fraction"},
                      {"s", "", "mm", "1/mm", ""},
                      {}};
        std::vector<double> density;
        for (std::size_t k = 0; k < times_.size(); ++k) {
            density.push_back(length_[k] / area);
            t.rows.push_back(
                {times_[k], static_cast<double>(steady_[k]), length_[k], density.back(), rich_[k]});
        }
        r.tables.push_back(std::move(t));
        r.scalars.push_back({"interface_length", "mm",
                             "length of the polar-rich / medium-rich interface, steady mean",
                             steady_estimate(length_, steady_)});
        r.scalars.push_back({"interface_density", "1/mm",
                             "interface length per box area, steady mean",
                             steady_estimate(density, steady_)});
        r.scalars.push_back({"polar_rich_fraction", "",
                             "fraction of the box that is polar-rich, steady mean",
                             steady_estimate(rich_, steady_)});
    }
    if (steady_frames_ == 0) r.notes.push_back("no steady frame: the averaged maps are NaN");
    return r;
}

}  // namespace rodsea
