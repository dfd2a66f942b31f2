target_sources(rodsea_core PRIVATE
  src/rodsea/analyze/analysis_frame.cpp
  src/rodsea/analyze/frame_context.cpp
  src/rodsea/analyze/observable.cpp
  src/rodsea/analyze/analysis_options.cpp
  src/rodsea/analyze/order_parameter_observable.cpp
  src/rodsea/analyze/pair_correlation_observable.cpp
  src/rodsea/analyze/corotating_maps_observable.cpp
  src/rodsea/analyze/autocorrelation_observable.cpp
  src/rodsea/analyze/flock_observable.cpp
  src/rodsea/analyze/segregation_observable.cpp
  src/rodsea/analyze/medium_velocity_observable.cpp
  src/rodsea/analyze/observable_registry.cpp
  src/rodsea/analyze/analyze_run.cpp
  src/rodsea/analyze/analysis_output.cpp
  src/rodsea/analyze/analyze_command.cpp
)
