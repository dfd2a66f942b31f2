#include "rodsea/engine/cpu/plate_noise.hpp"

#include <algorithm>

#include "rodsea/engine/cpu/detail/parallel.hpp"
#include "rodsea/engine/physics/plate_noise.hpp"

namespace rodsea::cpu {

namespace {

// The noise of hits[begin, end), sorted by body and plate, with `begin` and `end` on body
// boundaries: each body's fastest approach to each plate, then the one rule of physics/.
size_t kick(const std::vector<PlateHit>& hits, size_t begin, size_t end, BodyView bodies,
            const SpeciesTable& species, const StepContext& step) {
    size_t kicks = 0;
    for (size_t i = begin; i < end;) {
        const std::uint32_t body = hits[i].body;
        physics::PlateApproach approach;
        for (; i < end && hits[i].body == body; ++i) {
            double& fastest = hits[i].plate == kLidPlate ? approach.lid : approach.base;
            fastest = std::max(fastest, hits[i].approach_speed);
        }
        if (species.polar[bodies.species[body]])
            kicks += static_cast<size_t>(
                physics::apply_plate_noise(bodies.spin[body].z, step.noise_mode, step.noise_epsilon,
                                           step.seed, step.step, body, approach));
    }
    return kicks;
}

// Below this many hits a thread team costs more than the kicks.
constexpr size_t kHitsWorthThreads = 1024;

}  // namespace

size_t apply_plate_noise(std::vector<PlateHit>& hits, BodyView bodies, const SpeciesTable& species,
                         const StepContext& step, int threads) {
    // Under add, ε = 0 changes nothing; under set it still stops the spin of every rod that hit.
    if ((step.noise_mode == physics::NoiseMode::add && step.noise_epsilon == 0.0) || hits.empty())
        return 0;
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
