target_sources(rodsea_core PRIVATE
  src/rodsea/meanfield/mean_field.cpp
)
