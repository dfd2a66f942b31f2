// Campaign files: the grid they describe (product of axes, zipped axes, overrides, replicates,
// --scale) and the errors for bad ones, without running anything.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "rodsea/campaign/campaign_cost.hpp"
#include "rodsea/campaign/campaign_points.hpp"
#include "rodsea/campaign/slurm_executor.hpp"
#include "rodsea/config/campaign_file.hpp"
#include "rodsea/error.hpp"

namespace rodsea {
namespace {

const char* const kBase = R"(
[base.box]
side = 40.0
[[base.species]]
name = "polar"
kind = "polar_rod"
count = 20
[[base.species]]
name = "medium"
kind = "apolar_rod"
length = 2.5
area_fraction = 0.2
[base.time]
duration = 0.1
)";

CampaignGrid grid_of(const std::string& text, const CampaignScaling& scaling = {}) {
    return expand_campaign(load_campaign_string(std::string(kBase) + text, "test.toml"), scaling,
                           {});
}

TEST(CampaignFile, PointsAreTheProductOfTheAxesWithZippedKeysMovingTogether) {
    const CampaignGrid g = grid_of(R"(
[campaign]
replicates = 3
first_seed = 10
[[axis]]
key = "species.medium.area_fraction"
values = [0.1, 0.3]
[[axis]]
keys = ["species.medium.length", "drive.gamma"]
values = [[2.5, 7.0], [4.5, 5]]
[[override]]
when = { "species.medium.area_fraction" = 0.3, "species.medium.length" = 4.5 }
set = { "time.duration" = 0.2 }
)");
    ASSERT_EQ(g.points.size(), 4u);  // 2 × 2, the last axis fastest
    EXPECT_EQ(g.points[0].name, "medium.area_fraction=0.1,medium.length=2.5,gamma=7");
    EXPECT_EQ(g.points[3].name, "medium.area_fraction=0.3,medium.length=4.5,gamma=5");
    for (const CampaignPoint& p : g.points) {
        // Each point's plan has its coordinates: the medium's φ within one body's area of the
        // asked value, its length and Γ exactly.
        const double phi = std::get<double>(p.coordinates[0].second);
        const double length = std::get<double>(p.coordinates[1].second);
        EXPECT_NEAR(p.plan.engine.species[1].shape.extent, length, 1e-9) << p.name;
        EXPECT_NEAR(p.plan.requested_area_fraction[1], phi, 1e-12);
        EXPECT_EQ(p.plan.engine.drive.gamma, length == 2.5 ? 7.0 : 5.0);
        // Only the point matching both conditions of the override runs longer.
        EXPECT_EQ(p.plan.control.duration, phi == 0.3 && length == 4.5 ? 0.2 : 0.1) << p.name;
        EXPECT_EQ(p.plan.engine.seed, 10u);
    }
    ASSERT_EQ(g.runs.size(), 12u);
    EXPECT_EQ(g.runs[2].seed, 12u);
    EXPECT_EQ(g.runs[2].id, g.points[0].name + "/seed12");
}

TEST(CampaignFile, ScaleShrinksTheBoxKeepingAreaFractionsAndCountDensities) {
    const std::string text = R"(
[[axis]]
key = "species.medium.area_fraction"
values = [0.2]
)";
    const CampaignGrid full = grid_of(text);
    const CampaignGrid half = grid_of(text, {.scale = 0.5, .duration = 0.05});
    EXPECT_EQ(half.points[0].plan.engine.box.lx, 20.0);
    EXPECT_EQ(half.points[0].plan.control.duration, 0.05);
    EXPECT_EQ(half.points[0].plan.counts[0], 5);  // 20 polar rods × 0.5²
    // The medium's count follows its area fraction: a quarter, to within one rod.
    EXPECT_NEAR(static_cast<double>(half.points[0].plan.counts[1]),
                static_cast<double>(full.points[0].plan.counts[1]) / 4.0, 1.0);
}

struct BadCampaign {
    std::string text, message;
};

// Each campaign (the base above plus its text) is refused with a message holding its part.
void expect_refused(const std::vector<BadCampaign>& cases) {
    for (const BadCampaign& c : cases) {
        try {
            grid_of(c.text);
            ADD_FAILURE() << "accepted:\n" << c.text;
        } catch (const std::exception& e) {
            EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos)
                << c.text << "\n-> " << e.what();
        }
    }
}

TEST(CampaignFile, BadFilesAreRefusedByKeyWithTheAllowedValues) {
    const std::vector<BadCampaign> cases{
        {"[campain]\nname = \"x\"\n", "did you mean 'campaign'"},
        {"[campaign]\nreplicate = 2\n", "did you mean 'replicates'"},
        {"[campaign]\nreplicates = 0\n", "campaign.replicates"},
        {"[[axis]]\nkey = \"species.medium.area_fractoin\"\nvalues = [0.1]\n",
         "did you mean 'area_fraction'"},
        {"[[axis]]\nkey = \"drve.gamma\"\nvalues = [5.0]\n", "did you mean 'drive'"},
        {"[[axis]]\nkey = \"species.medium.area_fraction\"\nvalues = [0.95]\n", "(0, 0.9069]"},
        {"[[axis]]\nkey = \"species.beads.area_fraction\"\nvalues = [0.1]\n", "polar, medium"},
        {"[[axis]]\nkey = \"species.medium.area_fraction\"\nvalues = []\n", "axis[0].values"},
        {"[[axis]]\nkey = \"species.medium.area_fraction\"\nvalues = [0.1, 0.1]\n",
         "each value once"},
        {"[[axis]]\nkeys = [\"drive.gamma\", \"drive.frequency\"]\nvalues = [[5.0]]\n",
         "an array of 2 values"},
        {"[[axis]]\nkey = \"initial.orientation\"\nvalues = [\"isotropc\"]\n",
         "did you mean \"isotropic\""},
        {"[[axis]]\nkey = \"drive.gamma\"\nvalues = [5.0]\n[[figure]]\nname = \"f\"\nx = "
         "\"drive.gama\"\ny = [\"P_polar\"]\n",
         "did you mean 'drive.gamma'"},
        {"[[axis]]\nkey = \"drive.gamma\"\nvalues = [5.0]\n[[figure]]\nname = \"f\"\nkind = "
         "\"snapshots\"\n",
         "did you mean 'snapshot'"},
        {"[[axis]]\nkey = \"drive.gamma\"\nvalues = [5.0]\n[[figure]]\nname = \"f\"\nkind = "
         "\"map\"\nx = \"drive.gamma\"\ny = [\"P_polar\"]\n",
         "figure[0].series"},
        {"[[axis]]\nkey = \"drive.gamma\"\nvalues = [5.0]\n[[figure]]\nname = \"f\"\nkind = "
         "\"analysis\"\nplot = \"g_r_teta\"\n",
         "did you mean 'g_r_theta'"},
        {"[[axis]]\nkey = \"drive.gamma\"\nvalues = [5.0]\n[[figure]]\nname = \"f\"\nkind = "
         "\"snapshot\"\nx = \"drive.gamma\"\n",
         "no x for kind \"snapshot\""},
        {"[[axis]]\nkey = \"drive.gamma\"\nvalues = [5.0]\n[[figure]]\nname = \"f\"\nkind = "
         "\"movie\"\nwhen = { \"drive.gamma\" = 6.0 }\n",
         "figure[0].when.drive.gamma = 6: allowed a value of the axis: 5"},
        {"[campaign]\nname = \"fig 1\"\n", "campaign.name"},
        {"[[axis]]\nkey = \"drive.gamma\"\nvalues = [5.0]\n[[figure]]\nname = \"f\"\nkind = "
         "\"movie\"\n[[figure]]\nname = \"f\"\nkind = \"snapshot\"\n",
         "a name no other figure has"},
        {"[[override]]\nset = { \"time.durration\" = 1.0 }\n", "did you mean 'duration'"},
        {"[campaign]\nbase = \"missing.toml\"\n", "missing.toml"},
        // What `collect` asks of the analysis, refused before hours of runs, not at collect.
        {"[analysis]\nobservables = [\"order\", \"nematic\"]\n",
         "analysis.observables = nematic: allowed order, pair"},
        {"[analysis]\nobservables = [\"flock\"]\n", "did you mean 'flocks'"},
        // Named as the file writes it, not as analyze's --param.
        {"[analysis]\nparameters = { \"flocks.epss\" = 2.0 }\n",
         "analysis.parameters.flocks.epss = an unknown key"},
        {"[analysis]\nparameters = { \"flocks.epss\" = 2.0 }\n", "did you mean 'flocks.eps'"},
        {"[analysis]\nparameters = { \"flocks.eps\" = -1.0 }\n",
         "invalid analysis.parameters.flocks.eps = -1"},
        // A window the runs do not reach (the base's 0.1 s), or reversed.
        {"[analysis]\nto = 0.5\n",
         "invalid analysis.to = 0.5 s: allowed at most the runs' last frame (0.1 s at campaign "
         "point"},
        {"[analysis]\nfrom = 0.2\n", "invalid analysis.from = 0.2 s: allowed at most the runs'"},
        // Off the output grid the last frame (0.1 s) is before the duration (0.105 s).
        {"[[override]]\nset = { \"time.duration\" = 0.105 }\n[analysis]\nto = 0.103\n",
         "at most the runs' last frame (0.1 s"},
        // Between two frames (the default output interval is far above 0.1 ms).
        {"[analysis]\nfrom = 0.0501\nto = 0.0502\n", "that holds a frame"},
        // Runs that stop when steady end where each becomes steady, not at a known time.
        {"[[override]]\nset = { \"time.duration\" = 10.0, \"time.steady_samples\" = 10 }\n"
         "[analysis]\nto = 5.0\n",
         "no analysis.to where runs stop when steady"},
        {"[analysis]\nfrom = 0.05\nto = 0.02\n",
         "invalid analysis.to = 0.02 s: allowed at least analysis.from (0.05 s)"},
    };
    expect_refused(cases);
}

// A run config where a campaign file belongs (examples/paper/'s base-*.toml beside the
// campaigns) is named as one, not refused for its [box].
TEST(CampaignFile, ARunConfigIsNamedAsOne) {
    try {
        load_campaign_string("[box]\nside = 38.0\n[time]\nduration = 1.0\n", "base-rods.toml");
        ADD_FAILURE() << "a run config accepted as a campaign";
    } catch (const InvalidParameter& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("base-rods.toml"), std::string::npos) << what;
        EXPECT_NE(what.find("this is a run config"), std::string::npos) << what;
    }
}

// A point must run what its name says: its axis values are not replaced by
// an override, the seeds stay the replicates', and a zipped axis cannot set a key beside its
// alternative, which a single config refuses.
TEST(CampaignFile, APointRunsWhatItsNameSays) {
    const std::vector<BadCampaign> cases{
        {"[[axis]]\nkey = \"species.medium.area_fraction\"\nvalues = [0.1, 0.3]\n"
         "[[override]]\nwhen = { \"species.medium.area_fraction\" = 0.1 }\n"
         "set = { \"species.medium.area_fraction\" = 0.3 }\n",
         "override[0].set = species.medium.area_fraction: allowed a key no axis sets"},
        {"[[axis]]\nkey = \"run.seed\"\nvalues = [1, 2]\n",
         "axis = run.seed: allowed a config key other than run.seed"},
        {"[[override]]\nset = { \"run.seed\" = 7 }\n",
         "override[0].set = run.seed: allowed a config key other than run.seed"},
        {"[[axis]]\nkeys = [\"species.medium.length\", \"species.medium.aspect_ratio\"]\n"
         "values = [[2.5, 3.125], [3.0, 3.75]]\n",
         "species.medium.aspect_ratio and species.medium.length: allowed one of them"},
        // Two overrides that both apply to a point and set one key: which would it run?
        {"[[axis]]\nkey = \"drive.gamma\"\nvalues = [5.0, 7.0]\n"
         "[[override]]\nset = { \"time.duration\" = 0.2 }\n"
         "[[override]]\nwhen = { \"drive.gamma\" = 7.0 }\nset = { \"time.duration\" = 0.3 }\n",
         "time.duration set twice: allowed each key once per point"},
    };
    expect_refused(cases);
    // What stays allowed: an axis over the alternative of a key the base gives (the base's
    // length gives way to the axis's aspect ratio), and overrides of other keys.
    const CampaignGrid grid = grid_of(
        "[[axis]]\nkey = \"species.medium.aspect_ratio\"\nvalues = [3.125, 5.0]\n"
        "[[override]]\nwhen = { \"species.medium.aspect_ratio\" = 5.0 }\n"
        "set = { \"time.duration\" = 0.2 }\n");
    ASSERT_EQ(grid.points.size(), 2u);
    EXPECT_DOUBLE_EQ(grid.points[1].plan.control.duration, 0.2);
}

// A grid too large to plan is refused at once, with its size and cost, not expanded for minutes.
TEST(CampaignFile, AGridTooLargeToPlanIsRefusedBeforeItIsExpanded) {
    const auto axis = [](const std::string& key, int n, double first) {
        std::string values;
        for (int i = 0; i < n; ++i)
            values += (i ? ", " : "") + std::to_string(first + 0.001 * i);
        return "[[axis]]\nkey = \"" + key + "\"\nvalues = [" + values + "]\n";
    };
    const std::string cube = axis("drive.gamma", 30, 5.0) + axis("time.duration", 30, 0.1) +
                             axis("species.medium.area_fraction", 30, 0.1);
    try {
        grid_of(cube);
        FAIL() << "27 000 points were expanded";
    } catch (const InvalidParameter& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("30 x 30 x 30 points x 1 replicates = 27000 runs"), std::string::npos)
            << what;
        EXPECT_NE(what.find("at most 10000 points"), std::string::npos) << what;
        EXPECT_NE(what.find("sphere-steps"), std::string::npos) << what;
    }
    // Few points with many replicates count by their runs.
    try {
        grid_of("[campaign]\nreplicates = 1000\n" + axis("drive.gamma", 200, 5.0));
        FAIL() << "200 000 runs were expanded";
    } catch (const InvalidParameter& e) {
        EXPECT_NE(std::string(e.what()).find("= 200000 runs"), std::string::npos) << e.what();
    }
}

TEST(CampaignFile, ImpossiblePackingsAreRefusedBeforeAnythingRuns) {
    try {
        grid_of("[[axis]]\nkey = \"species.medium.area_fraction\"\nvalues = [0.2, 0.88]\n");
        FAIL() << "a packing of 0.88 + polar rods was accepted";
    } catch (const InvalidParameter& e) {
        EXPECT_NE(std::string(e.what()).find("medium.area_fraction=0.88"), std::string::npos)
            << e.what();
    }
}

TEST(CampaignFile, TheDocsKeyReferenceIsTheKeyTable) {
    std::ifstream in(std::string(RODSEA_SOURCE_DIR) + "/docs/campaigns.md");
    std::stringstream text;
    text << in.rdbuf();
    const std::string reference = campaign_reference_markdown();
    const std::string doc = text.str();
    ASSERT_GE(doc.size(), reference.size());
    EXPECT_EQ(doc.substr(doc.size() - reference.size()), reference)
        << "docs/campaigns.md ends with the key reference: regenerate its end with `rodsea "
           "campaign --reference`";
}

TEST(SlurmTime, ReadsEveryFormOfSbatchTimeAndRefusesTheRest) {
    EXPECT_EQ(parse_slurm_time("90"), 90 * 60);                // minutes
    EXPECT_EQ(parse_slurm_time("2:30"), 150);                  // MM:SS
    EXPECT_EQ(parse_slurm_time("12:00:00"), 12 * 3600);        // HH:MM:SS
    EXPECT_EQ(parse_slurm_time("2-12"), 60 * 3600);            // D-HH
    EXPECT_EQ(parse_slurm_time("1-00:30"), 24 * 3600 + 1800);  // D-HH:MM
    EXPECT_EQ(parse_slurm_time("1-00:00:10"), 24 * 3600 + 10);
    // Under a minute, past a year, or not sbatch's syntax.
    for (const char* bad : {"", "0:30", "1h", "12:00:00:00", "-5", "1:-3", "400-00", "1.5"})
        EXPECT_THROW(parse_slurm_time(bad), InvalidParameter) << bad;
}

// The plan's wall time. --jobs: processes take the runs in order, each as one frees (3 h, 1 h,
// 1 h, 1 h on two: the 3 h run holds one while the other takes the three 1 h runs); --threads
// divides each run's time. --ensemble: the runs dealt by cost to min(threads, runs) workers,
// whatever their order (the Fig. 4a campaign's 0.7, 0.4, 0.4 core-hours on two threads: 0.8 h),
// or in turn on every thread once there are two threads per run.
TEST(CampaignWallTime, JobsTakeRunsInOrderAnEnsembleDealsThemByCost) {
    const double h = 3600.0;
    EXPECT_DOUBLE_EQ(planned_wall_seconds({3 * h, h, h, h}, {.jobs = 2}), 3 * h);
    EXPECT_DOUBLE_EQ(planned_wall_seconds({h, h, h, 3 * h}, {.jobs = 2}), 4 * h);
    EXPECT_DOUBLE_EQ(planned_wall_seconds({3 * h, h, h, h}, {.jobs = 1, .threads = 2}), 3 * h);
    const std::vector<double> fig4a = {0.7 * h, 0.4 * h, 0.4 * h};
    EXPECT_DOUBLE_EQ(planned_wall_seconds(fig4a, {.threads = 2, .ensemble = true}), 0.8 * h);
    EXPECT_DOUBLE_EQ(planned_wall_seconds({h, h, h, 3 * h}, {.threads = 2, .ensemble = true}),
                     3 * h);
    EXPECT_DOUBLE_EQ(planned_wall_seconds(fig4a, {.threads = 6, .ensemble = true}), 1.5 * h / 6);
    EXPECT_DOUBLE_EQ(planned_wall_seconds({}, {.jobs = 4}), 0.0);
}

// The GPU-hours `campaign plan` gives come from the H200's measured steps (docs/performance.md,
// bench/gpu/results/h200-after.csv): the model stays within the 25 % it claims of each measured
// system, from the 10⁴-sphere mixture (49.9 µs per step) to the 10⁶ one (189 µs) and the
// ensemble of 64 × 10⁴ (176 µs); and an ensemble of small runs costs far less than the same runs
// one by one, since they share each step's ~50 µs of kernels.
TEST(CampaignGpuHours, FollowTheMeasuredStepsAndFavourEnsembles) {
    const std::pair<double, double> measured[] = {{9'990, 49.9e-6},   {99'916, 66.0e-6},
                                                  {375'962, 113e-6},  {999'204, 189e-6},
                                                  {111'470, 86.3e-6}, {639'360, 176e-6}};
    for (const auto& [spheres, seconds] : measured)
        EXPECT_NEAR(h200_step_seconds(spheres) / seconds, 1.0, 0.25) << spheres << " spheres";
    const GpuHours paper = h200_hours({{100'000'000, 375'962}});
    EXPECT_NEAR(paper.alone, 1e8 * 113e-6 / 3600.0, 0.15 * paper.alone);  // ~3.1 h
    EXPECT_DOUBLE_EQ(paper.ensemble, paper.alone);                        // one run: the same
    const std::vector<std::pair<std::uint64_t, std::uint64_t>> small(64, {1'000'000, 10'000});
    const GpuHours many = h200_hours(small);
    EXPECT_NEAR(many.alone, 64 * 1e6 * h200_step_seconds(1e4) / 3600.0, 1e-9);
    EXPECT_LT(many.ensemble, many.alone / 10);
    EXPECT_EQ(h200_hours({}).alone, 0.0);
}

// Run names cut to fit a column keep their ends, where a two-axis campaign's runs differ: cut
// at the end, the Fig. 4a campaign's three runs would read alike.
TEST(CampaignNames, NamesCutForAColumnKeepWhatTellsThemApart) {
    std::vector<std::string> cut;
    for (const char* sigma : {"1.25", "3.125", "5.625"}) {
        const std::string id =
            std::string("medium.area_fraction=0.75,medium.aspect_ratio=") + sigma + "/seed1";
        cut.push_back(name_in_column(id, 40));
        EXPECT_EQ(cut.back().size(), 40u) << cut.back();
        EXPECT_EQ(cut.back().rfind("medium.area_", 0), 0u) << cut.back();
        const std::string end = std::string("=") + sigma + "/seed1";
        EXPECT_EQ(cut.back().substr(cut.back().size() - end.size()), end) << cut.back();
        EXPECT_EQ(name_in_column(id, id.size()), id);
    }
    EXPECT_NE(cut[0], cut[1]);
    EXPECT_NE(cut[1], cut[2]);
    EXPECT_EQ(name_in_column("medium.area_fraction=0.75", 4), "medi");
}

}  // namespace
}  // namespace rodsea
