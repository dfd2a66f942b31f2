#include "rodsea/engine/cpu/plate_noise.hpp"

#include <algorithm>

#include "rodsea/engine/cpu/detail/parallel.hpp"
#include "rodsea/engine/physics/plate_noise.hpp"

namespace rodsea::cpu {

namespace {

// The kicks of hits[begin, end), sorted by body and plate, with `begin` and `end` on body
// boundaries.
size_t kick(const std::vector<PlateHit>& hits, size_t begin, size_t end, BodyView bodies,
            const SpeciesTable& species, const StepContext& step) {
    size_t kicks = 0;
    for (size_t i = begin; i < end;) {
        const PlateHit& first = hits[i];
        double speed = 0.0;
        size_t j = i;
        for (; j < end && hits[j].body == first.body && hits[j].plate == first.plate; ++j)
            speed = std::max(speed, hits[j].approach_speed);
        if (species.polar[bodies.species[first.body]]) {
            bodies.spin[first.body].z +=
                step.noise_epsilon * speed *
                physics::noise_sign(step.seed, step.step, first.body, first.plate);
            ++kicks;
        }
        i = j;
    }
    return kicks;
}

// Below this many hits a thread team costs more than the kicks.
constexpr size_t kHitsWorthThreads = 1024;

}  // namespace

size_t apply_plate_noise(std::vector<PlateHit>& hits, BodyView bodies, const SpeciesTable& species,
                         const StepContext& step, int threads) {
    if (step.noise_epsilon == 0.0 || hits.empty()) return 0;
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
        kicks += kick(hits, body_boundary(c.begin), body_boundary(c.end), bodies, species, step);
    }
    return kicks;
}

}  // namespace rodsea::cpu
