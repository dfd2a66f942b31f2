target_sources(rodsea_core PRIVATE
  src/rodsea/view/colour_wheel.cpp
  src/rodsea/view/frame_renderer.cpp
  src/rodsea/view/png_file.cpp
  src/rodsea/view/render_flags.cpp
  src/rodsea/view/frame_flags.cpp
  src/rodsea/view/render_command.cpp
  src/rodsea/view/ffmpeg_pipe.cpp
  src/rodsea/view/movie_command.cpp
  src/rodsea/view/plot_command.cpp
  src/rodsea/view/export_formats.cpp
  src/rodsea/view/export_command.cpp
)
