target_sources(rodsea_core PRIVATE
  src/rodsea/cli/arguments.cpp
  src/rodsea/cli/frame_flags.cpp
)
