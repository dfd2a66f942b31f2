#include "rodsea/analyze/defect_observable.hpp"

#include <cmath>
#include <limits>

namespace rodsea {

DefectObservable::DefectObservable(const AnalysisSetup& setup, const AnalysisOptions& options)
    : setup_(setup),
      cell_(options.field_cell),
      link_(options.defect_link),
      pair_(options.defect_pair),
      tracker_(setup.box, options.defect_link, options.defect_pair) {}

void DefectObservable::compute(const FrameContext& context) {
    const std::vector<NematicDefect>& defects = context.defects(cell_);
    double counts[4] = {0, 0, 0, 0}, charge = 0.0;
    for (const NematicDefect& d : defects) {
        charge += d.charge;
        counts[d.charge == 0.5 ? 0 : d.charge == -0.5 ? 1 : d.charge > 0 ? 2 : 3] += 1.0;
    }
    times_.push_back(context.frame().time);
    steady_.push_back(context.steady() ? 1 : 0);
    if (context.steady() && steady_from_ < 0.0) steady_from_ = context.frame().time;
    plus_half_.push_back(counts[0]);
    minus_half_.push_back(counts[1]);
    plus_one_.push_back(counts[2]);
    minus_one_.push_back(counts[3]);
    charge_.push_back(charge);
    tracker_.add_frame(context.frame().time, defects);
}

ObservableResults DefectObservable::finish() {
    ObservableResults r;
    r.observable = name();
    const FieldGrid grid = FieldGrid::of(setup_.box, cell_);
    r.parameters = {{"cell_x", grid.dx, "mm"},
                    {"cell_y", grid.dy, "mm"},
                    {"link", link_, "mm"},
                    {"pair", pair_, "mm"}};
    const double area = setup_.box.lx * setup_.box.ly;
    TableResult counts{
        "defect_counts",
        "nematic defects of the medium's director field per frame, by charge, and "
        "their total charge (0 on the torus)",
        {"time", "steady", "plus_half", "minus_half", "plus_one", "minus_one", "total_charge"},
        {"s", "", "", "", "", "", ""},
        {}};
    std::vector<double> density;
    for (std::size_t k = 0; k < times_.size(); ++k) {
        counts.rows.push_back({times_[k], static_cast<double>(steady_[k]), plus_half_[k],
                               minus_half_[k], plus_one_[k], minus_one_[k], charge_[k]});
        density.push_back((plus_half_[k] + minus_half_[k]) / area);
    }
    r.tables.push_back(std::move(counts));
    r.scalars.push_back({"plus_half_defects", "", "+1/2 defects per frame, steady mean",
                         steady_estimate(plus_half_, steady_)});
    r.scalars.push_back({"minus_half_defects", "", "−1/2 defects per frame, steady mean",
                         steady_estimate(minus_half_, steady_)});
    r.scalars.push_back({"defect_density", "1/mm²", "±1/2 defects per box area, steady mean",
                         steady_estimate(density, steady_)});

    // Events inside the steady window, as rates per box area.
    const double window = steady_seconds(setup_);
    std::size_t created = 0, annihilated = 0;
    TableResult events{"defect_events",
                       "defect events: kind 0 birth, 1 death, 2 ± pair creation, 3 ± pair "
                       "annihilation; the track(s) involved (second −1 for a lone event); time: "
                       "the first frame that shows the change",
                       {"time", "kind", "track", "partner"},
                       {"s", "", "", ""},
                       {}};
    for (const DefectEvent& e : tracker_.events()) {
        events.rows.push_back({e.time, static_cast<double>(e.kind),
                               static_cast<double>(e.tracks[0]),
                               e.tracks.size() > 1 ? static_cast<double>(e.tracks[1]) : -1.0});
        if (steady_from_ < 0.0 || e.time <= steady_from_) continue;
        created += e.kind == DefectEvent::Kind::creation ? 1 : 0;
        annihilated += e.kind == DefectEvent::Kind::annihilation ? 1 : 0;
    }
    r.tables.push_back(std::move(events));
    r.scalars.push_back({"pair_creation_rate", "1/(mm² s)",
                         "± pairs created per box area and second in the steady window",
                         rate_estimate(created, window, area)});
    r.scalars.push_back({"pair_annihilation_rate", "1/(mm² s)",
                         "± pairs annihilated per box area and second in the steady window",
                         rate_estimate(annihilated, window, area)});

    // Tracks: a row each, and every state in analysis.h5.
    TableResult tracks{
        "defect_tracks",
        "each defect's track: charge, first and last frame's time, frames, "
        "lifetime (last − first; a track still alive at the end is cut there), "
        "mean speed of its core, and whether it ended before the run did",
        {"track", "charge", "first", "last", "frames", "lifetime", "mean_speed", "ended"},
        {"", "", "s", "s", "", "s", "mm/s", ""},
        {}};
    const double last_time = times_.empty() ? 0.0 : times_.back();
    std::vector<double> lifetimes;
    std::vector<std::int32_t> id, charge2;
    std::vector<double> t, x, y, orientation;
    for (const DefectTrack& track : tracker_.tracks()) {
        double path = 0.0;
        for (std::size_t k = 1; k < track.states.size(); ++k) {
            const Vec3 d =
                setup_.box.minimum_image(Vec3{track.states[k].x - track.states[k - 1].x,
                                              track.states[k].y - track.states[k - 1].y, 0.0});
            path += std::hypot(d.x, d.y);
        }
        const double first = track.times.front(), last = track.times.back();
        const bool ended = last < last_time;
        const double speed =
            last > first ? path / (last - first) : std::numeric_limits<double>::quiet_NaN();
        tracks.rows.push_back({static_cast<double>(track.id), track.charge, first, last,
                               static_cast<double>(track.times.size()), last - first, speed,
                               ended ? 1.0 : 0.0});
        // Lifetimes of ±1/2 tracks that began after the window opened and ended before the run
        // did: tracks cut by either edge would bias the mean short.
        if (std::abs(track.charge) == 0.5 && ended && steady_from_ >= 0.0 && first > steady_from_)
            lifetimes.push_back(last - first);
        for (std::size_t k = 0; k < track.states.size(); ++k) {
            id.push_back(track.id);
            charge2.push_back(static_cast<std::int32_t>(std::lround(2.0 * track.charge)));
            t.push_back(track.times[k]);
            x.push_back(track.states[k].x);
            y.push_back(track.states[k].y);
            orientation.push_back(track.states[k].orientation);
        }
    }
    r.tables.push_back(std::move(tracks));
    r.scalars.push_back({"half_defect_lifetime", "s",
                         "mean lifetime of the ±1/2 tracks born and ended inside the steady "
                         "window",
                         estimate_mean(lifetimes)});
    const auto n = static_cast<std::uint64_t>(t.size());
    r.datasets.push_back(
        {"defects/track", "track of each defect of each frame (defect_tracks.csv)", "", {n}, id});
    r.datasets.push_back({"defects/time", "the frame's time", "s", {n}, t});
    r.datasets.push_back({"defects/x", "core position, x", "mm", {n}, x});
    r.datasets.push_back({"defects/y", "core position, y", "mm", {n}, y});
    r.datasets.push_back(
        {"defects/twice_charge", "twice the charge: ±1 for ±1/2, ±2 for ±1", "", {n}, charge2});
    r.datasets.push_back({"defects/orientation",
                          "orientation of a +1/2 defect (the direction of ∇·Q: from its head "
                          "towards its tail); NaN for the others",
                          "rad",
                          {n},
                          orientation});
    if (lifetimes.empty())
        r.notes.push_back("no ±1/2 track both began and ended inside the steady window");
    return r;
}

}  // namespace rodsea
