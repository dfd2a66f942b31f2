#include "rodsea/engine/plate_noise.hpp"

#include <algorithm>

#include "rodsea/engine/parallel.hpp"
#include "rodsea/random.hpp"

namespace rodsea {

double noise_sign(std::uint64_t seed, std::uint64_t step, std::uint32_t body, std::uint32_t plate) {
    std::uint64_t h = splitmix64(seed);
    h = splitmix64(h ^ step);
    h = splitmix64(h ^ ((static_cast<std::uint64_t>(body) << 1) | (plate == kBasePlate ? 0 : 1)));
    return (h >> 63) ? 1.0 : -1.0;
}

namespace {

// The kicks of hits[begin, end), sorted by body and plate, with `begin` and `end` on body
// boundaries.
size_t kick(const std::vector<PlateHit>& hits, size_t begin, size_t end, BodyState& bodies,
            const std::vector<Species>& species, double epsilon, std::uint64_t seed,
            std::uint64_t step) {
    size_t kicks = 0;
    for (size_t i = begin; i < end;) {
        const PlateHit& first = hits[i];
        double speed = 0.0;
        size_t j = i;
        for (; j < end && hits[j].body == first.body && hits[j].plate == first.plate; ++j)
            speed = std::max(speed, hits[j].approach_speed);
        if (species[bodies.species[first.body]].kind == BodyKind::polar_rod) {
            bodies.spin[first.body].z +=
                epsilon * speed * noise_sign(seed, step, first.body, first.plate);
            ++kicks;
        }
        i = j;
    }
    return kicks;
}

// Below this many hits a thread team costs more than the kicks.
constexpr size_t kHitsWorthThreads = 1024;

}  // namespace

size_t apply_plate_noise(std::vector<PlateHit>& hits, BodyState& bodies,
                         const std::vector<Species>& species, double epsilon, std::uint64_t seed,
                         std::uint64_t step, int threads) {
    if (epsilon == 0.0 || hits.empty()) return 0;
    std::sort(hits.begin(), hits.end(), [](const PlateHit& x, const PlateHit& y) {
        return x.body != y.body ? x.body < y.body : x.plate < y.plate;
    });
    // Each thread takes a chunk of the hits, moved to body boundaries so that both kicks of a body
    // that hit both plates come from one thread, in the serial order.
    const auto body_boundary = [&hits](size_t i) {
        while (i > 0 && i < hits.size() && hits[i].body == hits[i - 1].body)
            ++i;
        return i;
    };
    const int team = hits.size() >= kHitsWorthThreads ? threads : 1;
    size_t kicks = 0;
#pragma omp parallel num_threads(team) if (team > 1) reduction(+ : kicks)
    {
        const Chunk c = chunk_of(hits.size(), thread_index(), team_size());
        kicks += kick(hits, body_boundary(c.begin), body_boundary(c.end), bodies, species, epsilon,
                      seed, step);
    }
    return kicks;
}

}  // namespace rodsea
