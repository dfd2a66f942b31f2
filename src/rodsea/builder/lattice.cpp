#include "rodsea/builder/lattice.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rodsea/error.hpp"
#include "rodsea/math/periodic_box.hpp"

namespace rodsea {

double stacked_row_spacing(const Footprint& f, double pitch, double shift, double clearance) {
    const double reach = 2.0 * f.half_length + clearance;
    const auto k_lo = static_cast<long long>(std::ceil((-reach - shift) / pitch));
    const auto k_hi = static_cast<long long>(std::floor((reach - shift) / pitch));
    double spacing = 0.0;
    for (const double below : {1.0, -1.0}) {            // head/tail of the body in the lower row
        for (const double above : {1.0, -1.0}) {        // and of those in the upper row
            for (long long k = k_lo; k <= k_hi; ++k) {  // the upper-row bodies within reach
                const double x = shift + static_cast<double>(k) * pitch;
                for (size_t i = 0; i < f.size(); ++i) {
                    for (size_t j = 0; j < f.size(); ++j) {
                        const double dx = x + above * f.along[j] - below * f.along[i];
                        const double contact = f.radius[i] + f.radius[j] + clearance;
                        if (std::abs(dx) >= contact) continue;
                        const double dy = std::sqrt(contact * contact - dx * dx);
                        spacing = std::max(spacing, dy - above * f.across[j] + below * f.across[i]);
                    }
                }
            }
        }
    }
    return spacing;
}

namespace {

std::string describe(const std::vector<Species>& species, const std::vector<long long>& counts,
                     const LatticePlan& plan, const Box& box) {
    std::string m = "the rows of the lattice start do not fit:";
    for (size_t s = 0; s < species.size(); ++s) {
        const SpeciesRows& r = plan.species[s];
        if (counts[s] <= 0) continue;
        const double area = static_cast<double>(counts[s]) * species[s].shape.projected_area;
        m += " " + species[s].name + ": " + std::to_string(counts[s]) + " bodies need " +
             format_number(area) + " mm^2 (area fraction " +
             format_number(area / (box.lx * box.ly)) + "), as " + std::to_string(r.rows) +
             " rows of " + std::to_string(r.sites_per_row) + " sites they take " +
             format_number(r.height) + " mm of height;";
    }
    m += " together " + format_number(plan.height) +
         " mm, but the box offers box.ly = " + format_number(box.ly) + " mm (box area " +
         format_number(box.lx * box.ly) + " mm^2)";
    return m;
}

}  // namespace

namespace {

// One row of the lattice before the rows are laid out: where it goes among all rows, in (0, 1).
struct KeyedRow {
    double order;
    std::uint32_t species;
    long long count;
};

// Each species' rows: sites per row, pitch and spacing into plan.species, its rows (bodies spread
// evenly over them) appended to `keyed`. False, with plan.message, when a body does not fit.
bool plan_species_rows(const std::vector<Species>& species, const std::vector<Footprint>& feet,
                       const std::vector<long long>& counts, const Box& box, double clearance,
                       LatticePlan& plan, std::vector<KeyedRow>& keyed) {
    for (size_t s = 0; s < species.size(); ++s) {
        SpeciesRows& r = plan.species[s];
        r.count = counts[s];
        if (counts[s] < 0) {
            plan.message =
                species[s].name + ": a negative count (" + std::to_string(counts[s]) + " bodies)";
            return false;
        }
        if (counts[s] == 0) continue;
        const double pitch_min = species[s].shape.extent + clearance;
        const double scale = feet[s].rotatable ? 1.0 : plan.pitch_scale;
        r.sites_per_row = static_cast<long long>(std::floor(box.lx / (scale * pitch_min)));
        if (r.sites_per_row < 1) {
            plan.message = species[s].name + ": one body is " +
                           format_number(species[s].shape.extent) + " mm long and needs " +
                           format_number(pitch_min) +
                           " mm with the clearance, but box.lx = " + format_number(box.lx) + " mm";
            return false;
        }
        r.pitch = box.lx / static_cast<double>(r.sites_per_row);
        r.rows = (counts[s] + r.sites_per_row - 1) / r.sites_per_row;
        // Rows two apart are in register again: in a narrow box (one or two bodies per row) the
        // half-pitch shifted rows can slot into each other's gaps and leave those too close.
        r.stacked_spacing =
            std::max(stacked_row_spacing(feet[s], r.pitch, 0.5 * r.pitch, clearance),
                     0.5 * stacked_row_spacing(feet[s], r.pitch, 0.0, clearance));
        // Bodies spread evenly over the species' rows: each holds floor or ceil of the mean.
        for (long long i = 0; i < r.rows; ++i) {
            const long long count = (i + 1) * counts[s] / r.rows - i * counts[s] / r.rows;
            keyed.push_back({(static_cast<double>(i) + 0.5) / static_cast<double>(r.rows),
                             static_cast<std::uint32_t>(s), count});
        }
    }
    return true;
}

// The rows of all species interleaved by their order, starting at a change of species, so that
// the periodic seam between the last and the first row never splits a run of one species (whose
// rows must alternate their half-pitch shift).
void interleave(std::vector<KeyedRow>& keyed) {
    std::stable_sort(keyed.begin(), keyed.end(),
                     [](const KeyedRow& a, const KeyedRow& b) { return a.order < b.order; });
    size_t start = 0;
    for (size_t i = 0; i < keyed.size(); ++i) {
        if (keyed[i].species != keyed[(i + keyed.size() - 1) % keyed.size()].species) {
            start = i;
            break;
        }
    }
    std::rotate(keyed.begin(), keyed.begin() + static_cast<std::ptrdiff_t>(start), keyed.end());
}

// The rows bottom to top with the gap each needs to the next, and the height they take.
void lay_out_rows(const std::vector<KeyedRow>& keyed, const std::vector<Footprint>& feet,
                  double clearance, LatticePlan& plan) {
    const size_t n = keyed.size();
    for (size_t i = 0; i < n; ++i) {
        LatticeRow row;
        row.species = keyed[i].species;
        row.count = keyed[i].count;
        row.continues_run = i > 0 && keyed[i - 1].species == row.species;
        const std::uint32_t next = keyed[(i + 1) % n].species;
        const SpeciesRows& r = plan.species[row.species];
        if (next != row.species) {
            // Another species at an arbitrary phase: the widest discs may meet head on.
            row.gap_after = feet[row.species].half_width + feet[next].half_width + clearance;
            plan.species[row.species].height += 0.5 * row.gap_after;
            plan.species[next].height += 0.5 * row.gap_after;
        } else {
            if (i + 1 < n) {
                row.gap_after = r.stacked_spacing;
            } else {
                // A single species all round: the rows meet across the seam half a pitch apart
                // for an even number of rows, in register for an odd one.
                row.gap_after =
                    (n % 2 == 0) ? r.stacked_spacing
                                 : stacked_row_spacing(feet[row.species], r.pitch, 0.0, clearance);
            }
            plan.species[row.species].height += row.gap_after;
        }
        plan.height += row.gap_after;
        plan.rows.push_back(row);
    }
}

}  // namespace

LatticePlan plan_lattice(const std::vector<Species>& species, const std::vector<Footprint>& feet,
                         const std::vector<long long>& counts, const Box& box, double clearance,
                         double pitch_scale) {
    LatticePlan plan;
    plan.pitch_scale = pitch_scale;
    plan.species.resize(species.size());
    std::vector<KeyedRow> keyed;
    if (!plan_species_rows(species, feet, counts, box, clearance, plan, keyed)) {
        plan.fits = false;
        return plan;
    }
    if (keyed.empty()) return plan;
    interleave(keyed);
    lay_out_rows(keyed, feet, clearance, plan);
    if (plan.height > box.ly) {
        plan.fits = false;
        plan.message = describe(species, counts, plan, box);
    }
    return plan;
}

LatticePlan spread_lattice(const std::vector<Species>& species, const std::vector<Footprint>& feet,
                           const std::vector<long long>& counts, const Box& box, double clearance) {
    LatticePlan best = plan_lattice(species, feet, counts, box, clearance);
    if (!best.fits || best.rows.empty()) return best;
    const auto spread_enough = [&](const LatticePlan& p) {
        return p.fits && p.pitch_scale * p.height <= box.ly;
    };
    // The largest scale at which every stretched species still has a site per row.
    double longest = 0.0;
    for (size_t s = 0; s < species.size(); ++s) {
        if (counts[s] > 0 && !feet[s].rotatable)
            longest = std::max(longest, species[s].shape.extent + clearance);
    }
    if (longest == 0.0) return best;  // only rods: nothing is stretched
    double lo = 1.0, hi = box.lx / longest;
    const LatticePlan widest = plan_lattice(species, feet, counts, box, clearance, hi);
    if (spread_enough(widest)) return widest;
    // Bisection: the height jumps with the whole rows that floor() adds, so this finds a scale
    // that is spread enough, not necessarily the largest; the spare height is shared anyway.
    for (int i = 0; i < 40 && hi - lo > 1e-4; ++i) {
        const double mid = 0.5 * (lo + hi);
        LatticePlan p = plan_lattice(species, feet, counts, box, clearance, mid);
        if (spread_enough(p)) {
            lo = mid;
            best = std::move(p);
        } else {
            hi = mid;
        }
    }
    return best;
}

PlanarBodies place_lattice(const LatticePlan& plan, const std::vector<Species>& species,
                           const std::vector<Footprint>& feet, const Box& box,
                           InitialOrientation orientation, SplitMix64& rng) {
    PlanarBodies bodies;
    if (plan.rows.empty()) return bodies;
    const bool aligned = orientation == InitialOrientation::aligned;
    const double spare = (box.ly - plan.height) / static_cast<double>(plan.rows.size());
    double y = rng.uniform(0.0, box.ly);
    double phase = 0.0;
    for (const LatticeRow& row : plan.rows) {
        const SpeciesRows& r = plan.species[row.species];
        const Footprint& f = feet[row.species];
        phase = row.continues_run ? phase + 0.5 * r.pitch : rng.uniform(0.0, r.pitch);
        const double row_y = PeriodicBox2D::wrap(y, box.ly);
        // Filled sites floor((j + u) m / c): evenly spread, distinct since m >= c.
        const double u = rng.uniform();
        const auto m = static_cast<double>(r.sites_per_row), c = static_cast<double>(row.count);
        for (long long j = 0; j < row.count; ++j) {
            const double site = std::floor((static_cast<double>(j) + u) * m / c);
            const double x = PeriodicBox2D::wrap(phase + site * r.pitch, box.lx);
            double angle = 0.0;
            if (!f.rotatable) {
                angle = aligned ? 0.0 : rng.uniform(-std::numbers::pi, std::numbers::pi);
            } else {
                const bool keep_plus_x = orientation != InitialOrientation::isotropic &&
                                         species[row.species].kind == BodyKind::polar_rod;
                angle = (keep_plus_x || rng.uniform() < 0.5) ? 0.0 : std::numbers::pi;
            }
            bodies.add(row.species, x, row_y, angle);
        }
        y += row.gap_after + spare;
    }
    return bodies;
}

}  // namespace rodsea
