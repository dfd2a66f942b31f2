target_sources(rodsea_core PRIVATE
  src/rodsea/cli/arguments.cpp
  src/rodsea/cli/progress.cpp
  src/rodsea/cli/count_progress.cpp
  src/rodsea/cli/stop_signal.cpp
)
