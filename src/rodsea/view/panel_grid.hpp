#pragma once
// Several pictures side by side: a grid `columns` wide whose cells are as large as the largest
// panel, each panel centred in its cell under a strip with its label, on the renderer's white.
// Every size is even, as H.264 needs. Used by `rodsea movie RUN1 RUN2 ...`.
#include <string>
#include <utility>
#include <vector>

#include "rodsea/view/frame_renderer.hpp"

namespace rodsea {

class PanelGrid {
  public:
    // `sizes[i]` is panel i's width and height in pixels; one label per panel.
    PanelGrid(const std::vector<std::pair<int, int>>& sizes, std::vector<std::string> labels,
              int columns);

    int width() const { return width_; }
    int height() const { return height_; }
    int columns() const { return columns_; }
    int rows() const { return rows_; }

    // Lays `panels` (sized as given to the constructor) out into `grid`.
    void compose(const std::vector<Image>& panels, Image& grid) const;

  private:
    std::vector<std::pair<int, int>> sizes_;
    std::vector<std::string> labels_;
    int columns_ = 1, rows_ = 1;
    int cell_width_ = 0, cell_height_ = 0, strip_ = 0;
    int width_ = 0, height_ = 0;
    double font_ = 12.0;
};

}  // namespace rodsea
