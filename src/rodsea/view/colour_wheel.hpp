#pragma once
// Colours that carry meaning in the pictures. Directions are periodic, so their colour map must
// be too: the wheel runs once round the hues for a polar axis (period 2π) and twice for a
// nematic one (period π), so that θ and θ + π look alike. Neither map passes through the
// neutral grey of the medium or the white background.
#include <cstdint>

namespace rodsea {

struct Rgb {
    double r = 0.0, g = 0.0, b = 0.0;  // [0, 1]
};

// θ = 0 (axis along +x) is red, π/2 yellow-green, π cyan, 3π/2 violet (HSV hue = θ / 2π).
Rgb direction_colour(double theta);
// The same wheel at 2θ: an apolar rod's axis has no head.
Rgb nematic_colour(double theta);
// Flocks by rank (0 the largest, 1 the next, ...): well-separated hues; no flock (−1) dark
// grey.
Rgb label_colour(int label);

}  // namespace rodsea
