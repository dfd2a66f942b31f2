#pragma once
// How the initial state is built (builder/initial_state.hpp).

namespace rodsea {

enum class InitialOrientation { isotropic, aligned };

struct BuilderOptions {
    InitialOrientation orientation = InitialOrientation::isotropic;
    int randomisation_sweeps = 50;  // Monte Carlo sweeps after the lattice start, [0, 100000]
};

}  // namespace rodsea
