target_sources(rodsea_core PRIVATE
)
