target_sources(rodsea_core PRIVATE
  src/rodsea/run/series_recorder.cpp
  src/rodsea/run/plan_report.cpp
  src/rodsea/run/run_lock.cpp
  src/rodsea/run/run_driver.cpp
)
