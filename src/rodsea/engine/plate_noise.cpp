#include "rodsea/engine/plate_noise.hpp"

#include <algorithm>

#include "rodsea/random.hpp"

namespace rodsea {

double noise_sign(std::uint64_t seed, std::uint64_t step, std::uint32_t body, std::uint32_t plate) {
    std::uint64_t h = splitmix64(seed);
    h = splitmix64(h ^ step);
    h = splitmix64(h ^ ((static_cast<std::uint64_t>(body) << 1) | (plate == kBasePlate ? 0 : 1)));
    return (h >> 63) ? 1.0 : -1.0;
}

size_t apply_plate_noise(std::vector<PlateHit>& hits, BodyState& bodies,
                         const std::vector<Species>& species, double epsilon, std::uint64_t seed,
                         std::uint64_t step) {
    if (epsilon == 0.0 || hits.empty()) return 0;
    std::sort(hits.begin(), hits.end(), [](const PlateHit& x, const PlateHit& y) {
        return x.body != y.body ? x.body < y.body : x.plate < y.plate;
    });
    size_t kicks = 0;
    for (size_t i = 0; i < hits.size();) {
        const PlateHit& first = hits[i];
        double speed = 0.0;
        size_t j = i;
        for (; j < hits.size() && hits[j].body == first.body && hits[j].plate == first.plate; ++j)
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

}  // namespace rodsea
