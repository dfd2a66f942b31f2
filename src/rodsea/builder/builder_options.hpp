#pragma once
// How the initial state is built (builder/initial_state.hpp).

namespace rodsea {

enum class InitialOrientation { isotropic, aligned };

struct BuilderOptions {
    InitialOrientation orientation = InitialOrientation::isotropic;
    int randomisation_sweeps = 50;  // Monte Carlo sweeps after the start, [0, 100000]
    // Side of the domains of the mosaic start (polydomain.hpp), mm, [2, 10000]: used only above
    // the jamming of random packings. 20 mm is the smallest at which every dense point of the
    // paper's Table S1 relaxes (docs/builder.md).
    double domain_size = 20.0;
};

}  // namespace rodsea
