target_sources(rodsea_core PRIVATE
  src/rodsea/cli/arguments.cpp
)
