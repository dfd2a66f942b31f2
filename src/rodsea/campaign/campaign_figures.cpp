#include "rodsea/campaign/campaign_figures.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <ostream>
#include <sstream>

#include "rodsea/error.hpp"
#include "rodsea/io/atomic_file.hpp"
#include "rodsea/view/movie_command.hpp"
#include "rodsea/view/plot_command.hpp"
#include "rodsea/view/render_command.hpp"

namespace rodsea {

namespace fs = std::filesystem;

namespace {

// The first replicate of `point` that is done, if any.
const CampaignRun* first_finished(const CampaignPaths& paths, const CampaignGrid& grid,
                                  std::size_t point) {
    for (const CampaignRun& r : grid.runs)
        if (r.point == point && run_status(paths, r).state == RunState::done) return &r;
    return nullptr;
}

// A picture command run in this process, its lines passed on; the files it wrote are the lines
// that name existing files under `under`.
int picture(int (*command)(const std::vector<std::string>&, std::ostream&, std::ostream&),
            const std::vector<std::string>& words, const fs::path& under, FiguresDrawn& drawn,
            std::string& message) {
    std::ostringstream out, err;
    int code = 0;
    try {
        code = command(words, out, err);
    } catch (const std::exception& e) {
        err << e.what();
        code = 2;
    }
    std::istringstream lines(out.str());
    for (std::string line; std::getline(lines, line);) {
        std::error_code ec;
        if (line.rfind(under.string(), 0) == 0 && fs::is_regular_file(line, ec))
            drawn.files.emplace_back(line);
    }
    message = err.str();
    while (!message.empty() && message.back() == '\n')
        message.pop_back();
    return code;
}

std::string figure_label(const CampaignPoint& point) {
    std::string label;
    for (const KeySetting& c : point.coordinates)
        label += (label.empty() ? "" : ", ") + short_key(c.first) + " = " + setting_text(c.second);
    return label.empty() ? point.name : label;
}

}  // namespace

std::vector<std::size_t> figure_points(const CampaignFigure& figure, const CampaignGrid& grid) {
    std::vector<std::size_t> chosen;
    for (std::size_t p = 0; p < grid.points.size(); ++p) {
        const bool matches =
            std::all_of(figure.when.begin(), figure.when.end(), [&](const auto& condition) {
                const auto& [key, values] = condition;
                const auto c = std::find_if(grid.points[p].coordinates.begin(),
                                            grid.points[p].coordinates.end(),
                                            [&](const KeySetting& s) { return s.first == key; });
                return c != grid.points[p].coordinates.end() &&
                       std::any_of(values.begin(), values.end(), [&](const config::Value& v) {
                           return setting_text(v) == setting_text(c->second);
                       });
            });
        if (matches) chosen.push_back(p);
    }
    return chosen;
}

FiguresDrawn draw_campaign_figures(const CampaignPaths& paths, const Campaign& campaign,
                                   const CampaignGrid& grid, std::ostream& log) {
    FiguresDrawn drawn;
    const fs::path dir = paths.collected() / "figures";
    fs::create_directories(dir);

    // Curves and maps: one call of `rodsea plot` on a description of them all.
    nlohmann::json table_figures = nlohmann::json::array();
    std::vector<std::string> axis_columns;
    for (const CampaignAxis& a : campaign.axes)
        for (const std::string& k : a.keys)
            axis_columns.push_back(short_key(k));
    for (const CampaignFigure& f : campaign.figures) {
        if (f.kind != FigureKind::curve && f.kind != FigureKind::map) continue;
        nlohmann::json j{{"name", f.name},
                         {"kind", to_string(f.kind)},
                         {"x", short_key(f.x)},
                         {"y", f.y},
                         {"series", f.series.empty() ? "" : short_key(f.series)},
                         {"serieslabel", f.series_label},
                         {"axes", axis_columns},
                         {"xlabel", f.xlabel},
                         {"ylabel", f.ylabel},
                         {"title", f.title},
                         {"logx", f.logx},
                         {"logy", f.logy}};
        if (f.level) j["level"] = *f.level;
        nlohmann::json points = nlohmann::json::array();
        for (const std::size_t p : figure_points(f, grid))
            points.push_back(grid.points[p].name);
        j["points"] = points;
        table_figures.push_back(j);
    }
    if (!table_figures.empty()) {
        const nlohmann::json spec{
            {"rodsea_campaign_figures", 1}, {"table", "points.csv"}, {"figures", table_figures}};
        const fs::path json = paths.collected() / "figures.json";
        write_file_atomically(json, spec.dump(2) + "\n");
        std::string message;
        const int code =
            picture(plot_command, {json.string(), "-o", dir.string()}, dir, drawn, message);
        if (code != 0)
            drawn.problems.push_back("curves and maps: " + message);
        else if (!message.empty())
            log << message << "\n";  // the notes on figures skipped
    }

    for (const CampaignFigure& f : campaign.figures) {
        if (f.kind == FigureKind::curve || f.kind == FigureKind::map) continue;
        std::vector<std::pair<const CampaignPoint*, const CampaignRun*>> shown;
        std::size_t unfinished = 0;
        for (const std::size_t p : figure_points(f, grid)) {
            if (const CampaignRun* r = first_finished(paths, grid, p))
                shown.emplace_back(&grid.points[p], r);
            else
                ++unfinished;
        }
        if (unfinished)
            drawn.unfinished.push_back("figure " + f.name + ": " + std::to_string(unfinished) +
                                       " of its points have no finished run yet");
        if (shown.empty()) continue;
        std::string message;
        if (f.kind == FigureKind::movie) {
            std::vector<std::string> words;
            std::string labels;
            for (const auto& [point, run] : shown) {
                words.push_back(paths.run_dir(*run).string());
                std::string label = figure_label(*point);
                std::replace(label.begin(), label.end(), ',', ';');
                labels += (labels.empty() ? "" : ",") + label;
            }
            const fs::path mp4 = dir / (f.name + ".mp4");
            words.insert(words.end(), {"-o", mp4.string(), "--quiet"});
            if (shown.size() > 1) words.insert(words.end(), {"--labels", labels});
            if (picture(movie_command, words, dir, drawn, message) != 0)
                drawn.problems.push_back("figure " + f.name + ": " + message);
            else
                drawn.files.push_back(mp4);
            continue;
        }
        const fs::path folder = dir / f.name;
        for (const auto& [point, run] : shown) {
            const fs::path run_dir = paths.run_dir(*run);
            int code = 0;
            if (f.kind == FigureKind::snapshot) {
                const fs::path png = folder / (point->name + ".png");
                fs::create_directories(png.parent_path());
                code = picture(render_command, {run_dir.string(), "-o", png.string(), "--quiet"},
                               dir, drawn, message);
                if (code == 0) drawn.files.push_back(png);
            } else {
                const fs::path out = folder / point->name;
                const std::size_t before = drawn.files.size();
                code =
                    picture(plot_command,
                            {(run_dir / "analysis").string(), "-o", out.string(), "--only", f.plot},
                            dir, drawn, message);
                if (code == 0 && drawn.files.size() == before) {
                    code = 1;  // the run's analysis cannot give this figure: say why
                    if (message.empty()) message = "rodsea plot drew nothing";
                }
            }
            if (code != 0)
                drawn.problems.push_back("figure " + f.name + " at " + point->name + ": " +
                                         message);
        }
    }
    std::sort(drawn.files.begin(), drawn.files.end());
    drawn.files.erase(std::unique(drawn.files.begin(), drawn.files.end()), drawn.files.end());
    return drawn;
}

}  // namespace rodsea
