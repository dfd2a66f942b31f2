#include "rodsea/view/detail/render_flags.hpp"

#include "rodsea/error.hpp"

namespace rodsea {

std::vector<OptionSpec> picture_options(const std::string& size_help) {
    return {
        {"--size", "W", size_help},
        {"--region", "X0,X1,Y0,Y1", "show only this part of the box, mm (default: the whole box)"},
        {"--colour", "C",
         "polar rods: direction (cyclic colour wheel of the axis θ, thick → thin; default), "
         "flock (DBSCAN label, as `rodsea analyze`), uniform"},
        {"--medium", "M",
         "apolar rods: neutral (default) or nematic (wheel of 2θ: θ and θ+π alike)"},
        {"--flock-eps", "E", "DBSCAN radius for --colour flock, mm (default ℓ_p / 2)"},
        {"--no-annotations", "", "no text, scale bar or legend"},
        {"--overlay", "LIST",
         "drawn over the bodies, comma-separated: defects (the medium's nematic defects: +1/2 "
         "a red comet along its orientation, −1/2 a blue trefoil), director (a stick per cell "
         "along the medium's director, ∝ S), flock-tracks (each flock's centre over the last "
         "--trail s, an arrow along its heading, a ring on its leading rod)"},
        {"--overlay-cell", "C",
         "cell side of the director grid for defects and director, mm (default ℓ_p, as "
         "`rodsea analyze` fields.cell)"},
        {"--trail", "T", "seconds of each flock's path drawn by flock-tracks (default 2)"},
    };
}

namespace {

std::vector<double> split_numbers(const std::string& flag, const std::string& text) {
    std::vector<double> values;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        values.push_back(parse_number(flag, text.substr(start, comma - start), -1e9, 1e9, "mm"));
        start = comma + 1;
    }
    return values;
}

}  // namespace

RenderOptions render_options_from(const Arguments& args, int default_width) {
    RenderOptions o;
    o.width = static_cast<int>(parse_count(
        "--size", args.value("--size").value_or(std::to_string(default_width)), 64, 16384));
    if (const auto region = args.value("--region")) {
        const std::vector<double> v = split_numbers("--region", *region);
        if (v.size() != 4)
            throw InvalidParameter("--region", *region, "four numbers X0,X1,Y0,Y1 in mm");
        o.region = ViewRegion{v[0], v[1], v[2], v[3]};
    }
    if (const auto colour = args.value("--colour")) {
        if (*colour == "direction")
            o.polar = PolarColouring::direction;
        else if (*colour == "flock")
            o.polar = PolarColouring::flock;
        else if (*colour == "uniform")
            o.polar = PolarColouring::uniform;
        else
            throw InvalidParameter("--colour", *colour, "direction, flock or uniform");
    }
    if (const auto medium = args.value("--medium")) {
        if (*medium == "neutral")
            o.medium = MediumColouring::neutral;
        else if (*medium == "nematic")
            o.medium = MediumColouring::nematic;
        else
            throw InvalidParameter("--medium", *medium, "neutral or nematic");
    }
    if (const auto eps = args.value("--flock-eps")) {
        if (o.polar != PolarColouring::flock)
            throw InvalidParameter("--flock-eps", *eps, "only with --colour flock",
                                   "it sets the DBSCAN radius of the flock colours");
        o.flock_eps = parse_number("--flock-eps", *eps, 1e-3, 1e6, "mm");
    }
    if (const auto list = args.value("--overlay")) {
        std::size_t start = 0;
        while (start <= list->size()) {
            const std::size_t comma = std::min(list->find(',', start), list->size());
            const std::string name = list->substr(start, comma - start);
            if (name == "defects")
                o.overlay.defects = true;
            else if (name == "director")
                o.overlay.director = true;
            else if (name == "flock-tracks")
                o.overlay.flock_tracks = true;
            else
                throw InvalidParameter("--overlay", name,
                                       "a comma-separated list of defects, director, flock-tracks");
            start = comma + 1;
        }
    }
    for (const char* flag : {"--overlay-cell", "--trail"})
        if (args.value(flag) && !o.overlay.any())
            throw InvalidParameter(flag, *args.value(flag), "only with --overlay");
    if (const auto cell = args.value("--overlay-cell"))
        o.overlay.cell = parse_number("--overlay-cell", *cell, 1e-3, 1e6, "mm");
    if (const auto trail = args.value("--trail"))
        o.overlay.trail = parse_number("--trail", *trail, 0.0, 1e6, "s");
    o.annotate = !args.has("--no-annotations");
    return o;
}

std::string describe(const RenderOptions& options, const FrameRenderer& renderer) {
    const char* polar = options.polar == PolarColouring::direction ? "direction"
                        : options.polar == PolarColouring::flock   ? "flock"
                                                                   : "uniform";
    std::string s = std::to_string(renderer.width()) + "×" + std::to_string(renderer.height()) +
                    " px, polar rods by " + polar + ", medium " +
                    (options.medium == MediumColouring::nematic ? "by nematic axis" : "neutral");
    const ViewRegion& r = renderer.region();
    if (options.region)
        s += ", view x " + format_number(r.x0) + "–" + format_number(r.x1) + " y " +
             format_number(r.y0) + "–" + format_number(r.y1) + " mm";
    else
        s += ", whole box";
    if (options.overlay.any()) {
        std::string list;
        for (const auto& [on, name] : {std::pair{options.overlay.defects, "defects"},
                                       {options.overlay.director, "director"},
                                       {options.overlay.flock_tracks, "flock tracks"}})
            if (on) list += (list.empty() ? "" : " and ") + std::string(name);
        s += ", overlay " + list;
    }
    return s;
}

void report_written(std::ostream& out, const std::filesystem::path& output,
                    std::chrono::steady_clock::time_point start) {
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out << "wrote " << output.string() << " (" << format_number(seconds) << " s)\n";
}

}  // namespace rodsea
