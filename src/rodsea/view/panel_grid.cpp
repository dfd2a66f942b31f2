#include "rodsea/view/panel_grid.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rodsea {

namespace {

int even_up(int n) {
    return n + (n % 2);
}

// `text` without its first character (UTF-8: a lead byte and its continuation bytes).
std::string without_first_character(const std::string& text) {
    std::size_t k = 1;
    while (k < text.size() && (static_cast<unsigned char>(text[k]) & 0xC0) == 0x80)
        ++k;
    return text.substr(std::min(k, text.size()));
}

}  // namespace

PanelGrid::PanelGrid(const std::vector<std::pair<int, int>>& sizes, std::vector<std::string> labels,
                     int columns)
    : sizes_(sizes), labels_(std::move(labels)) {
    if (sizes_.empty() || labels_.size() != sizes_.size() || columns < 1)
        throw std::logic_error("PanelGrid: one label per panel and at least one column");
    columns_ = std::min<int>(columns, static_cast<int>(sizes_.size()));
    rows_ = (static_cast<int>(sizes_.size()) + columns_ - 1) / columns_;
    for (const auto& [w, h] : sizes_) {
        cell_width_ = std::max(cell_width_, w);
        cell_height_ = std::max(cell_height_, h);
    }
    // A label as large as the renderer's annotations on a panel of this width.
    font_ = std::max(11.0, static_cast<double>(cell_width_) / 32.0);
    strip_ = even_up(static_cast<int>(std::ceil(1.7 * font_)));
    cell_width_ = even_up(cell_width_);
    cell_height_ = even_up(cell_height_ + strip_);
    width_ = columns_ * cell_width_;
    height_ = rows_ * cell_height_;
}

void PanelGrid::compose(const std::vector<Image>& panels, Image& grid) const {
    if (panels.size() != sizes_.size())
        throw std::logic_error("PanelGrid::compose: one image per panel");
    grid.width = width_;
    grid.height = height_;
    grid.pixels.assign(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_),
                       0xffffffffu);
    cairo_surface_t* surface =
        cairo_image_surface_create_for_data(reinterpret_cast<unsigned char*>(grid.pixels.data()),
                                            CAIRO_FORMAT_ARGB32, width_, height_, width_ * 4);
    cairo_t* cr = cairo_create(surface);
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    cairo_set_font_size(cr, font_);
    for (std::size_t i = 0; i < panels.size(); ++i) {
        const Image& panel = panels[i];
        const int column = static_cast<int>(i) % columns_, row = static_cast<int>(i) / columns_;
        const double x0 = column * cell_width_, y0 = row * cell_height_;
        const double left = x0 + 0.5 * (cell_width_ - panel.width);
        cairo_surface_t* source = cairo_image_surface_create_for_data(
            reinterpret_cast<unsigned char*>(const_cast<std::uint32_t*>(panel.pixels.data())),
            CAIRO_FORMAT_ARGB32, panel.width, panel.height, panel.width * 4);
        cairo_set_source_surface(cr, source, std::floor(left), y0 + strip_);
        cairo_paint(cr);
        cairo_surface_destroy(source);
        // The label, centred in its strip, shortened from the left if it would not fit.
        std::string label = labels_[i];
        cairo_text_extents_t extents;
        cairo_text_extents(cr, label.c_str(), &extents);
        const std::string ellipsis = "…";
        while (extents.x_advance > cell_width_ - font_ && label.size() > ellipsis.size() + 1) {
            const std::string rest =
                label.rfind(ellipsis, 0) == 0 ? label.substr(ellipsis.size()) : label;
            label = ellipsis + without_first_character(rest);
            cairo_text_extents(cr, label.c_str(), &extents);
        }
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        cairo_move_to(cr, x0 + 0.5 * (cell_width_ - extents.x_advance),
                      y0 + 0.5 * strip_ + 0.35 * font_);
        cairo_show_text(cr, label.c_str());
    }
    cairo_surface_flush(surface);
    const cairo_status_t status = cairo_status(cr);
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
    if (status != CAIRO_STATUS_SUCCESS)
        throw std::runtime_error(std::string("drawing the panel grid: ") +
                                 cairo_status_to_string(status));
}

}  // namespace rodsea
