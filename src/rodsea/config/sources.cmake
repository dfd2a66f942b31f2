target_sources(rodsea_core PRIVATE
  src/rodsea/config/run_plan.cpp
  src/rodsea/config/config_values.cpp
  src/rodsea/config/schema.cpp
  src/rodsea/config/did_you_mean.cpp
  src/rodsea/config/read_toml.cpp
  src/rodsea/config/species_keys.cpp
  src/rodsea/config/resolve.cpp
  src/rodsea/config/write_toml.cpp
  src/rodsea/config/choices.cpp
  src/rodsea/config/reference_doc.cpp
  src/rodsea/config/config_file.cpp
)
