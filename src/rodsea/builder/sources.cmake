target_sources(rodsea_core PRIVATE
  src/rodsea/builder/footprint.cpp
  src/rodsea/builder/placement.cpp
  src/rodsea/builder/lattice.cpp
  src/rodsea/builder/disc_grid.cpp
  src/rodsea/builder/random_insertion.cpp
  src/rodsea/builder/monte_carlo.cpp
  src/rodsea/builder/initial_state.cpp
)
