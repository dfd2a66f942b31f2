#include "rodsea/cli/free_cores.hpp"

#include <sched.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

namespace rodsea {

FreeCoreMonitor::FreeCoreMonitor() {
    cpu_set_t set;
    CPU_ZERO(&set);
    if (::sched_getaffinity(0, sizeof set, &set) == 0) usable_ = std::max(1, CPU_COUNT(&set));
    machine_cores_ = std::max<int>(usable_, static_cast<int>(::sysconf(_SC_NPROCESSORS_ONLN)));
    last_ = read();
}

FreeCoreMonitor::Reading FreeCoreMonitor::read() {
    Reading r;
    std::ifstream stat("/proc/stat");
    std::string line;
    if (std::getline(stat, line) && line.rfind("cpu ", 0) == 0) {
        std::istringstream fields(line.substr(4));
        std::uint64_t value = 0;
        for (int k = 0; fields >> value; ++k) {
            r.total_ticks += value;
            if (k != 3 && k != 4) r.busy_ticks += value;  // idle and iowait are free time
        }
    }
    rusage own{};
    if (::getrusage(RUSAGE_SELF, &own) == 0)
        r.own_cpu_seconds = static_cast<double>(own.ru_utime.tv_sec + own.ru_stime.tv_sec) +
                            1e-6 * static_cast<double>(own.ru_utime.tv_usec + own.ru_stime.tv_usec);
    return r;
}

double FreeCoreMonitor::sample() {
    const Reading now = read();
    const double ticks_per_second = static_cast<double>(::sysconf(_SC_CLK_TCK));
    const double total = static_cast<double>(now.total_ticks - last_.total_ticks);
    const double wall = total / ticks_per_second / machine_cores_;
    if (now.total_ticks <= last_.total_ticks || wall < 0.05) return usable_;
    const double busy_cores =
        static_cast<double>(now.busy_ticks - last_.busy_ticks) / total * machine_cores_;
    const double own_cores = (now.own_cpu_seconds - last_.own_cpu_seconds) / wall;
    last_ = now;
    const double others = std::max(0.0, busy_cores - own_cores);
    return std::clamp(static_cast<double>(machine_cores_) - others, 0.0,
                      static_cast<double>(usable_));
}

int threads_for_free_cores(int requested, double free_cores) {
    return std::clamp(static_cast<int>(std::floor(free_cores + 0.25)), 1, requested);
}

}  // namespace rodsea
