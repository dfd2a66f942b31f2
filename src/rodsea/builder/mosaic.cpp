#include "rodsea/builder/mosaic.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "rodsea/builder/disc_grid.hpp"
#include "rodsea/builder/lattice.hpp"
#include "rodsea/builder/random_insertion.hpp"
#include "rodsea/math/periodic_box.hpp"

namespace rodsea {

namespace {

// Guests are few and dilute (polar rods at φ_p ≤ 0.2): random insertion needs a few attempts
// each.
constexpr double kGuestAttemptsPerBody = 100.0;

// Domain centres sit on a grid, each moved by up to this part of a cell: the cells vary in size
// and shape, but none is much larger than the others, and a point's nearest centre is always
// within two cells of its own.
constexpr double kJitter = 0.3;

struct Domains {
    int nx = 1, ny = 1;
    double wx = 0.0, wy = 0.0;        // grid cell, mm
    std::vector<double> x, y, angle;  // centre (mm) and director (rad) of each domain

    // The domain whose centre is nearest to (px, py) in the box, with the minimum image.
    int nearest(double px, double py, const PeriodicBox2D& box) const {
        const int cx = std::min(nx - 1, static_cast<int>(px / wx));
        const int cy = std::min(ny - 1, static_cast<int>(py / wy));
        int best = 0;
        double best_d2 = INFINITY;
        for (int dy = -2; dy <= 2; ++dy) {
            for (int dx = -2; dx <= 2; ++dx) {
                const int k = ((cy + dy) % ny + ny) % ny * nx + ((cx + dx) % nx + nx) % nx;
                const Vec3 d = box.minimum_image({px - x[k], py - y[k], 0.0});
                const double d2 = d.x * d.x + d.y * d.y;
                if (d2 < best_d2) best_d2 = d2, best = k;
            }
        }
        return best;
    }
};

// Each domain's share of the box, from the nearest centre of every point of a fine grid.
std::vector<double> domain_areas(const Domains& d, const Box& box) {
    constexpr int kPointsPerDomainSide = 24;
    const int mx = kPointsPerDomainSide * d.nx, my = kPointsPerDomainSide * d.ny;
    const PeriodicBox2D periodic{box.lx, box.ly};
    std::vector<double> area(d.x.size(), 0.0);
    for (int j = 0; j < my; ++j)
        for (int i = 0; i < mx; ++i)
            area[static_cast<size_t>(
                d.nearest((i + 0.5) * box.lx / mx, (j + 0.5) * box.ly / my, periodic))] += 1.0;
    return area;
}

// |Σ a_k e^{2iθ_k}| / Σ a_k: the nematic order of domains of areas a_k and directors θ_k.
double domains_order(const std::vector<double>& area, const std::vector<double>& angle) {
    double c = 0.0, s = 0.0, total = 0.0;
    for (size_t k = 0; k < area.size(); ++k) {
        c += area[k] * std::cos(2.0 * angle[k]);
        s += area[k] * std::sin(2.0 * angle[k]);
        total += area[k];
    }
    return std::hypot(c, s) / total;
}

// Directors for the domains: independent random ones leave the medium with S ≈ 1/√domains, far
// above the chance level 1/√N of its N bodies in a small box (0.27, 0.63 and 0.23 at φ_a = 0.80
// in the 38, 63 and 88 mm boxes, with 4, 9 and 16 domains). So the n directors are evenly spaced
// over π from a random origin, and dealt to the domains in the order, of kDeals random ones, whose
// area-weighted nematic order is least: the domains' Q tensors cancel but for the few bodies a
// domain gains or loses at its boundary.
std::vector<double> balanced_directors(const std::vector<double>& area, SplitMix64& rng) {
    constexpr int kDeals = 256;
    const size_t n = area.size();
    const double origin = rng.uniform(0.0, std::numbers::pi);
    std::vector<double> spaced(n), best, trial(n);
    for (size_t k = 0; k < n; ++k)
        spaced[k] = origin + std::numbers::pi * static_cast<double>(k) / static_cast<double>(n);
    best = spaced;
    double best_order = domains_order(area, best);
    std::vector<size_t> deal(n);
    for (int t = 0; t < kDeals && n > 2; ++t) {
        for (size_t k = 0; k < n; ++k)
            deal[k] = k;
        for (size_t k = n - 1; k > 0; --k)
            std::swap(
                deal[k],
                deal[std::min(k, static_cast<size_t>(rng.uniform() * static_cast<double>(k + 1)))]);
        for (size_t k = 0; k < n; ++k)
            trial[k] = spaced[deal[k]];
        if (const double order = domains_order(area, trial); order < best_order)
            best_order = order, best = trial;
    }
    return best;
}

Domains cut_into_domains(const Box& box, double size, SplitMix64& rng) {
    Domains d;
    d.nx = std::max(1, static_cast<int>(std::lround(box.lx / size)));
    d.ny = std::max(1, static_cast<int>(std::lround(box.ly / size)));
    d.wx = box.lx / d.nx;
    d.wy = box.ly / d.ny;
    for (int j = 0; j < d.ny; ++j) {
        for (int i = 0; i < d.nx; ++i) {
            d.x.push_back((i + 0.5 + rng.uniform(-kJitter, kJitter)) * d.wx);
            d.y.push_back((j + 0.5 + rng.uniform(-kJitter, kJitter)) * d.wy);
        }
    }
    d.angle = balanced_directors(domain_areas(d, box), rng);
    return d;
}

// The host's sites in every domain: rows along the domain's director with the lattice start's
// pitch and row spacing, a random phase per domain, random head/tail per site; a site belongs to
// the domain whose centre is nearest its body centre.
PlanarBodies host_sites(const Footprint& f, double extent, std::uint32_t host, const Domains& d,
                        const Box& box, double clearance, SplitMix64& rng) {
    const double pitch = extent + clearance;
    const double spacing = std::max(stacked_row_spacing(f, pitch, 0.5 * pitch, clearance),
                                    0.5 * stacked_row_spacing(f, pitch, 0.0, clearance));
    const PeriodicBox2D periodic{box.lx, box.ly};
    // A cell lies within 2 grid cells of its centre (kJitter < 1/2).
    const double reach = 2.0 * std::hypot(d.wx, d.wy);
    const long long ni = static_cast<long long>(std::ceil(reach / pitch));
    const long long nj = static_cast<long long>(std::ceil(reach / spacing));
    PlanarBodies sites;
    for (size_t k = 0; k < d.x.size(); ++k) {
        const double c = std::cos(d.angle[k]), s = std::sin(d.angle[k]);
        const double phase_x = rng.uniform(0.0, pitch), phase_y = rng.uniform(0.0, spacing);
        for (long long j = -nj; j <= nj; ++j) {
            const double v = phase_y + static_cast<double>(j) * spacing;
            const double shift = (j & 1) != 0 ? 0.5 * pitch : 0.0;
            for (long long i = -ni; i <= ni; ++i) {
                const double u = phase_x + shift + static_cast<double>(i) * pitch;
                if (u * u + v * v > reach * reach) continue;
                // Each point of the box once: only the minimum image of the site.
                const double ox = c * u - s * v, oy = s * u + c * v;
                if (2.0 * std::abs(ox) >= box.lx || 2.0 * std::abs(oy) >= box.ly) continue;
                const double x = PeriodicBox2D::wrap(d.x[k] + ox, box.lx);
                const double y = PeriodicBox2D::wrap(d.y[k] + oy, box.ly);
                if (d.nearest(x, y, periodic) != static_cast<int>(k)) continue;
                // Rods get random head/tail; a body without an axis a random angle, which its
                // discs do not see.
                double angle = rng.uniform(-std::numbers::pi, std::numbers::pi);
                if (f.rotatable) {
                    const double flip = rng.uniform() < 0.5 ? std::numbers::pi : 0.0;
                    angle = std::remainder(d.angle[k] + flip, 2.0 * std::numbers::pi);
                }
                sites.add(host, x, y, angle);
            }
        }
    }
    return sites;
}

std::uint32_t host_species(const std::vector<Species>& species,
                           const std::vector<long long>& counts) {
    std::uint32_t host = 0;
    for (std::uint32_t s = 1; s < species.size(); ++s) {
        if (static_cast<double>(counts[s]) * species[s].shape.projected_area >
            static_cast<double>(counts[host]) * species[host].shape.projected_area)
            host = s;
    }
    return host;
}

// The first `count` of `items` after a partial Fisher–Yates shuffle: a uniform random choice.
template <class T>
void choose(std::vector<T>& items, size_t count, SplitMix64& rng) {
    count = std::min(count, items.size());
    for (size_t i = 0; i < count; ++i) {
        const size_t j =
            i + static_cast<size_t>(rng.uniform() * static_cast<double>(items.size() - i));
        std::swap(items[i], items[std::min(j, items.size() - 1)]);
    }
    items.resize(count);
}

}  // namespace

MosaicResult mosaic_start(const std::vector<Species>& species, const std::vector<Footprint>& feet,
                          const std::vector<long long>& counts, const Box& box,
                          const MosaicOptions& options, SplitMix64& rng, PlanarBodies& bodies) {
    MosaicResult result;
    result.host = host_species(species, counts);
    const std::uint32_t host = result.host;
    const size_t wanted = static_cast<size_t>(std::max(0LL, counts[host]));

    std::vector<long long> guest_counts = counts;
    guest_counts[host] = 0;
    const InsertionResult guests =
        insert_randomly(species, feet, guest_counts, box, options.clearance,
                        options.guest_orientation, kGuestAttemptsPerBody, rng, bodies);
    result.guest_attempts = guests.attempts;
    if (!guests.complete) return result;

    // Beads have no direction to randomise, and boundaries between their crystals only cost
    // room: a host without an axis is one crystal, turned to a random angle.
    result.domain_size = feet[host].rotatable ? options.domain_size : std::max(box.lx, box.ly);
    const Domains domains = cut_into_domains(box, result.domain_size, rng);
    result.domains = static_cast<int>(domains.x.size());
    const PlanarBodies sites = host_sites(feet[host], species[host].shape.extent, host, domains,
                                          box, options.lattice_clearance, rng);
    result.sites = static_cast<long long>(sites.size());

    // Sites in random order, each kept if it clears the guests and the sites kept before it.
    const size_t n_guests = bodies.size();
    std::vector<std::uint32_t> body_species = bodies.species;
    body_species.resize(n_guests + sites.size(), host);
    DiscGrid grid(body_species, feet, box, options.clearance);
    for (std::uint32_t b = 0; b < n_guests; ++b)
        grid.insert_body(b, bodies.x[b], bodies.y[b], bodies.angle[b]);
    std::vector<std::uint32_t> order(sites.size());
    for (std::uint32_t i = 0; i < order.size(); ++i)
        order[i] = i;
    choose(order, order.size(), rng);
    std::vector<std::uint32_t> clear, clashing;
    for (const std::uint32_t i : order) {
        const auto b = static_cast<std::uint32_t>(n_guests + i);
        if (grid.trial(b, sites.x[i], sites.y[i], sites.angle[i])) {
            grid.insert_body(b, sites.x[i], sites.y[i], sites.angle[i]);
            clear.push_back(i);
        } else {
            clashing.push_back(i);
        }
    }
    result.clashes = static_cast<long long>(clashing.size());

    std::vector<std::uint32_t> kept = clear;
    choose(kept, wanted, rng);
    if (kept.size() < wanted) {
        choose(clashing, wanted - kept.size(), rng);
        kept.insert(kept.end(), clashing.begin(), clashing.end());
    }
    if (kept.size() < wanted) return result;  // fewer sites than bodies: the domains are too small
    std::sort(kept.begin(), kept.end());      // neighbours in a domain stay neighbours in memory
    for (const std::uint32_t i : kept)
        bodies.add(host, sites.x[i], sites.y[i], sites.angle[i]);

    result.relaxed = clear.size() < wanted;
    if (result.relaxed) {
        OverlapRelaxationOptions relax;
        relax.clearance = options.clearance;
        relax.max_iterations = options.max_iterations;
        result.relaxation = relax_overlaps(bodies, feet, box, relax);
        if (!result.relaxation.converged) return result;
    }
    result.complete = true;
    return result;
}

}  // namespace rodsea
