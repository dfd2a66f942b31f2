// rodsea: command-line entry. For now one command, `demo`, runs the built-in default scene.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <string_view>

#include "rodsea/app/demo.hpp"
#include "rodsea/error.hpp"

namespace {

constexpr const char* kUsage =
    R"(rodsea — vibrated granular rods: polar rods in a sea of apolar rods

usage:
  rodsea demo [options]   run the built-in default scene and write CSV output
  rodsea --help           this text
  rodsea --version

demo options:
  --periods N     simulated drive periods (5 ms each at 200 Hz)     [default 40]
  --box L         side of the square periodic box, mm               [default 30]
  --epsilon E     rotational noise strength of polar rods, 1/mm      [default 0]
  --seed S        random seed (initial orientations, noise signs)    [default 1]
  --out DIR       output directory                                  [default out/demo]
  --quiet         no progress lines

The demo scene: polar rods (l_p = 4.5 mm) at area fraction 0.05 among apolar rods
(l_a = 2.5 mm) at 0.30, plates at Gamma = 7, 200 Hz, gap 1.5 mm, dt = 5 us.
Draw the result with: /usr/bin/python3 scripts/plot_snapshot.py DIR
)";

double parse_number(std::string_view flag, const char* text) {
    char* end = nullptr;
    const double v = std::strtod(text, &end);
    if (end == text || *end != '\0')
        throw rodsea::InvalidParameter(std::string(flag), std::string("'") + text + "'",
                                       "a number");
    return v;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2 || std::string_view(argv[1]) == "--help" || std::string_view(argv[1]) == "-h") {
        std::cout << kUsage;
        return argc < 2 ? 2 : 0;
    }
    const std::string_view command = argv[1];
    if (command == "--version") {
        std::cout << "rodsea " << RODSEA_VERSION << "\n";
        return 0;
    }
    if (command != "demo") {
        std::cerr << "rodsea: unknown command '" << command << "' (commands: demo; see --help)\n";
        return 2;
    }
    rodsea::DemoOptions options;
    try {
        for (int i = 2; i < argc; ++i) {
            const std::string_view flag = argv[i];
            if (flag == "--quiet") {
                options.quiet = true;
                continue;
            }
            if (flag == "--help" || flag == "-h") {
                std::cout << kUsage;
                return 0;
            }
            constexpr std::string_view kValued[] = {"--periods", "--box", "--epsilon", "--seed",
                                                    "--out"};
            if (std::find(std::begin(kValued), std::end(kValued), flag) == std::end(kValued)) {
                std::cerr << "rodsea: unknown option '" << flag
                          << "' (demo options: --periods --box --epsilon --seed --out --quiet)\n";
                return 2;
            }
            if (i + 1 >= argc)
                throw rodsea::InvalidParameter(std::string(flag), "nothing", "a value after it");
            const char* value = argv[++i];
            if (flag == "--periods") {
                options.drive_periods = parse_number(flag, value);
            } else if (flag == "--box") {
                options.box_side = parse_number(flag, value);
            } else if (flag == "--epsilon") {
                options.noise_epsilon = parse_number(flag, value);
            } else if (flag == "--seed") {
                const double seed = parse_number(flag, value);
                if (seed < 0 || seed != std::floor(seed) || seed > 9.0e15)
                    throw rodsea::InvalidParameter("--seed", value, "an integer in [0, 9e15]");
                options.seed = static_cast<std::uint64_t>(seed);
            } else {
                options.out_dir = value;
            }
        }
        return rodsea::run_demo(options, std::cout);
    } catch (const rodsea::InvalidParameter& e) {
        std::cerr << "rodsea: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "rodsea: " << e.what() << "\n";
        return 1;
    }
}
