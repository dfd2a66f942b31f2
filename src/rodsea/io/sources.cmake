target_sources(rodsea_core PRIVATE
  src/rodsea/io/hdf5.cpp
  src/rodsea/io/atomic_file.cpp
  src/rodsea/io/trajectory_file.cpp
  src/rodsea/io/trajectory_reader.cpp
  src/rodsea/io/series_csv.cpp
  src/rodsea/io/checkpoint.cpp
  src/rodsea/io/stored_run.cpp
  src/rodsea/io/analysis_h5.cpp
  src/rodsea/io/output_path.cpp
)
