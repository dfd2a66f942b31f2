#pragma once
// How the initial state is built (builder/initial_state.hpp).

namespace rodsea {

// isotropic: every body at a random angle. aligned: every rod along ±x, polar rods +x (a lattice
// above random insertion's limit, so a dense medium starts aligned too). polar_aligned: the polar
// rods along +x in an isotropic medium, at every density: an ordered state's survival, tested
// without waiting for it to form.
enum class InitialOrientation { isotropic, aligned, polar_aligned };

struct BuilderOptions {
    InitialOrientation orientation = InitialOrientation::isotropic;
    int randomisation_sweeps = 50;  // Monte Carlo sweeps after the start, [0, 100000]
    // Side of the domains of the mosaic start (polydomain.hpp), mm, [2, 10000]: used only above
    // the jamming of random packings. 20 mm is the smallest at which every dense point of the
    // paper's Table S1 relaxes (docs/builder.md).
    double domain_size = 20.0;
};

}  // namespace rodsea
