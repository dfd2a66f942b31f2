target_sources(rodsea_core PRIVATE
  src/rodsea/analysis/statistics.cpp
  src/rodsea/analysis/pair_correlation.cpp
  src/rodsea/analysis/corotating_maps.cpp
  src/rodsea/analysis/flock_contour.cpp
  src/rodsea/analysis/time_correlation.cpp
  src/rodsea/analysis/dbscan.cpp
  src/rodsea/analysis/segregation.cpp
  src/rodsea/analysis/medium_velocity.cpp
)
