target_sources(rodsea_core PRIVATE
  src/rodsea/calibration/single_body_experiment.cpp
  src/rodsea/calibration/calibration_grid.cpp
  src/rodsea/calibration/calibration_table.cpp
  src/rodsea/calibration/calibrate_command.cpp
)
