#include "rodsea/shape/sphere_chain.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "rodsea/error.hpp"

namespace rodsea {

namespace {

// Centres equally spaced from x_first to x_last; diameter from the profile at each centre.
template <class Profile>
SphereList chain(int count, double x_first, double x_last, Profile diameter_at) {
    SphereList spheres;
    spheres.reserve(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) {
        const double s = count == 1 ? 0.5 : static_cast<double>(i) / (count - 1);
        const double x = x_first + s * (x_last - x_first);
        spheres.push_back({{x, 0.0, 0.0}, 0.5 * diameter_at(x, s)});
    }
    return spheres;
}

void require_ends_fit(const std::string& prefix, double length, double end_extent) {
    if (end_extent > length) {
        throw InvalidParameter(prefix + ".length", format_number(length) + " mm",
                               ">= " + format_number(end_extent) + " mm",
                               "the end spheres must fit inside the rod");
    }
}

}  // namespace

int ApolarRodGeometry::default_sphere_count(double length_mm) {
    return std::max(1, static_cast<int>(std::lround(4.0 * length_mm - 1.0)));
}

ApolarRodGeometry ApolarRodGeometry::with_length(double length_mm) {
    ApolarRodGeometry g;
    g.length = length_mm;
    g.sphere_count = default_sphere_count(length_mm);
    return g;
}

SphereList polar_rod_spheres(const PolarRodGeometry& g) {
    require_positive("polar_rod.length", g.length, "mm");
    require_positive("polar_rod.thick_diameter", g.thick_diameter, "mm");
    require_positive("polar_rod.thin_diameter", g.thin_diameter, "mm");
    require_positive_count("polar_rod.sphere_count", g.sphere_count);
    if (g.sphere_count < 2) {
        throw InvalidParameter("polar_rod.sphere_count", std::to_string(g.sphere_count), ">= 2",
                               "a polar rod needs a thick and a thin end");
    }
    const double r_thick = 0.5 * g.thick_diameter, r_thin = 0.5 * g.thin_diameter;
    require_ends_fit("polar_rod", g.length, r_thick + r_thin);
    return chain(g.sphere_count, -0.5 * g.length + r_thick, 0.5 * g.length - r_thin,
                 [&](double, double s) {
                     return g.thick_diameter + s * (g.thin_diameter - g.thick_diameter);
                 });
}

SphereList apolar_rod_spheres(const ApolarRodGeometry& g) {
    require_positive("apolar_rod.length", g.length, "mm");
    require_positive("apolar_rod.centre_diameter", g.centre_diameter, "mm");
    require_positive("apolar_rod.end_diameter", g.end_diameter, "mm");
    require_positive_count("apolar_rod.sphere_count", g.sphere_count);
    const double r_end = 0.5 * g.end_diameter;
    if (g.sphere_count == 1) {
        return {{{0.0, 0.0, 0.0}, 0.5 * g.centre_diameter}};
    }
    require_ends_fit("apolar_rod", g.length, 2.0 * r_end);
    const double x_end = 0.5 * g.length - r_end;
    return chain(g.sphere_count, -x_end, x_end, [&](double x, double) {
        const double u = x_end > 0.0 ? std::abs(x) / x_end : 0.0;
        return g.centre_diameter + u * (g.end_diameter - g.centre_diameter);
    });
}

SphereList bead_spheres(const BeadGeometry& g) {
    require_positive("bead.diameter", g.diameter, "mm");
    return {{{0.0, 0.0, 0.0}, 0.5 * g.diameter}};
}

}  // namespace rodsea
