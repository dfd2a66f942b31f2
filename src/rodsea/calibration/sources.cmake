target_sources(rodsea_core PRIVATE
  src/rodsea/calibration/single_body_experiment.cpp
)
