#include "rodsea/run/ensemble_loop.hpp"

#include <algorithm>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <thread>

#include "rodsea/cli/exit_codes.hpp"
#include "rodsea/cli/free_cores.hpp"
#include "rodsea/cli/stop_signal.hpp"
#include "rodsea/engine/state_check.hpp"

namespace rodsea {

namespace {

// Steps the ensemble until every session's run has ended, each as its session decides.
// `codes[i]` receives session i's exit code. The progress follows the run with the most steps
// left; a run's messages end the bar's line first.
class EnsembleLoop {
  public:
    EnsembleLoop(Ensemble& ensemble, std::vector<RunSession*> sessions, int threads,
                 ProgressStyle style, std::ostream& out, std::ostream& err)
        : ensemble_(ensemble),
          active_(std::move(sessions)),
          requested_threads_(threads),
          threads_(threads),
          style_(style),
          out_(out),
          err_(err) {
        for (std::size_t m = 0; m < active_.size(); ++m)
            active_[m]->attach(ensemble_, m);
    }

    // Session i's exit code by its place in the sessions given.
    std::vector<int> run() {
        std::vector<int> codes(active_.size(), kExitOk);
        for (std::size_t m = 0; m < active_.size(); ++m)
            order_.push_back(m);
        follow_lead();
        for (RunSession* s : active_)
            s->write_progress("running", 0.0);
        if (const int signal = stop_signal_received(); signal != 0)  // during the build
            return stop_all(signal, codes);
        if (requested_threads_ > 1) {
            std::this_thread::sleep_for(std::chrono::milliseconds(100));  // a first measure
            adapt_threads();
        }
        // Read only when a frame, an end or a progress file needs it: it reads the clock.
        const std::function<double()> rate = [this] { return progress_->steps_per_second(); };
        const RunSession::BeforePrinting settle = [this] { settle_progress(); };
        while (!active_.empty()) {
            const std::uint64_t steps = steps_this_time();
            const auto started = std::chrono::steady_clock::now();
            try {
                ensemble_.run(steps);
            } catch (const BlowUpError&) {
                // Each system's blow-up is read below; the others stepped as usual.
            }
            pace(steps, seconds_since(started));
            std::vector<std::size_t> ended;
            for (std::size_t m = 0; m < active_.size(); ++m) {
                RunSession& s = *active_[m];
                std::optional<int> code;
                if (const std::optional<BlowUp>& b = ensemble_.blow_up(m)) {
                    settle_progress();
                    code = s.stop_after_blow_up(*b, s.step_count(), rate(), out_, err_);
                } else {
                    code = s.after_step(rate, out_, err_, style_, settle);
                }
                if (code) {
                    codes[order_[m]] = *code;
                    ended.push_back(m);
                }
            }
            if (!settled_) progress_->update(lead_->step_count(), lead_->polar_order());
            if (const int signal = stop_signal_received(); signal != 0) {
                retire(ended);
                return stop_all(signal, codes);
            }
            for (std::size_t m = 0; m < active_.size(); ++m) {
                if (std::find(ended.begin(), ended.end(), m) != ended.end()) continue;
                if (const auto code = active_[m]->between_steps(rate(), err_, settle)) {
                    codes[order_[m]] = *code;
                    ended.push_back(m);
                }
            }
            if (seconds_since(last_threads_check_) >= kThreadsCheckSeconds) adapt_threads();
            if (!ended.empty()) retire(ended);
        }
        return codes;
    }

  private:
    static double seconds_since(std::chrono::steady_clock::time_point t) {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    }

    // The ensemble steps in runs (a device reads its statistics once per run): up to the next
    // step at which some session has a frame to write or ends, no more than 1 % of the lead
    // run's steps (the progress moves by at most that), and short enough in wall time that a
    // signal, a checkpoint or the progress waits at most about kRunSeconds.
    std::uint64_t steps_this_time() const {
        std::uint64_t steps =
            std::min(steps_per_run_, std::max<std::uint64_t>(1, lead_->plan().total_steps() / 100));
        for (const RunSession* s : active_)
            steps = std::min(steps, s->steps_to_next_output());
        return steps;
    }
    // Runs grow while they take well under kRunSeconds and shrink when they take more.
    void pace(std::uint64_t steps, double seconds) {
        if (steps < steps_per_run_) return;  // cut short by an output: says nothing
        if (seconds < 0.25 * kRunSeconds && steps_per_run_ < kMostStepsPerRun)
            steps_per_run_ *= 2;
        else if (seconds > kRunSeconds && steps_per_run_ > 1)
            steps_per_run_ /= 2;
    }

    // The progress follows the run with the most steps left (the first of them), from here.
    void follow_lead() {
        if (active_.empty()) return;
        lead_ = active_.front();
        for (RunSession* s : active_)
            if (s->steps_left() > lead_->steps_left()) lead_ = s;
        progress_ = std::make_unique<ProgressReporter>(out_, style_, lead_->step_count(),
                                                       lead_->plan().total_steps(),
                                                       lead_->plan().engine.dt);
        settled_ = false;
        if (active_.size() > 1 && style_ != ProgressStyle::quiet)
            out_ << "progress: " << lead_->dir().string()
                 << ", the run with the most steps left of " << active_.size() << std::endl;
    }

    // Ends the progress line before a message; a new one starts after the step.
    void settle_progress() {
        if (settled_) return;
        progress_->finish(lead_->step_count(), lead_->polar_order());
        settled_ = true;
    }

    // Drops the runs that ended from the ensemble; the others step on, bit for bit.
    void retire(std::vector<std::size_t> ended) {
        if (ended.empty()) return;
        std::sort(ended.begin(), ended.end());
        ensemble_.retire(ended);
        for (std::size_t k = ended.size(); k-- > 0;) {
            active_.erase(active_.begin() + static_cast<std::ptrdiff_t>(ended[k]));
            order_.erase(order_.begin() + static_cast<std::ptrdiff_t>(ended[k]));
        }
        for (std::size_t m = 0; m < active_.size(); ++m)
            active_[m]->attach(ensemble_, m);
        if (settled_) follow_lead();
    }

    std::vector<int> stop_all(int signal, std::vector<int>& codes) {
        settle_progress();
        const double rate = progress_->steps_per_second();
        for (std::size_t m = 0; m < active_.size(); ++m)
            codes[order_[m]] = active_[m]->stop_on_signal(signal, rate, out_, err_);
        return codes;
    }

    // Steps on as many of the threads asked for as other processes leave cores free
    // (FreeCoreMonitor): more threads than free cores spin against each other. Said once when
    // it first differs.
    void adapt_threads() {
        last_threads_check_ = std::chrono::steady_clock::now();
        if (requested_threads_ <= 1) return;
        const int use = threads_for_free_cores(requested_threads_, cores_.sample());
        if (use == threads_) return;
        ensemble_.set_threads(use);
        threads_ = use;
        if (style_ != ProgressStyle::quiet && !told_threads_) {
            out_ << "\nthreads: stepping on " << use << " of run.threads = " << requested_threads_
                 << ", as other processes leave " << use << " core" << (use == 1 ? "" : "s")
                 << " free (rechecked every " << kThreadsCheckSeconds
                 << " s; the trajectory does not depend on it)\n"
                 << std::flush;
            told_threads_ = true;
        }
    }

    Ensemble& ensemble_;
    std::vector<RunSession*> active_;
    std::vector<std::size_t> order_;  // each active session's place in the sessions given
    RunSession* lead_ = nullptr;
    std::unique_ptr<ProgressReporter> progress_;
    bool settled_ = true;
    int requested_threads_, threads_;
    ProgressStyle style_;
    std::ostream& out_;
    std::ostream& err_;
    FreeCoreMonitor cores_;
    bool told_threads_ = false;
    std::chrono::steady_clock::time_point last_threads_check_ = std::chrono::steady_clock::now();
    static constexpr double kThreadsCheckSeconds = 2.0;
    static constexpr double kRunSeconds = 0.5;
    static constexpr std::uint64_t kMostStepsPerRun = std::uint64_t{1} << 20;
    std::uint64_t steps_per_run_ = 1;
};

}  // namespace

void step_to_the_end(Ensemble& ensemble, const std::vector<RunSession*>& by_system,
                     const std::vector<std::size_t>& run_of, std::vector<int>& codes, int threads,
                     bool name_runs, ProgressStyle style, std::ostream& out, std::ostream& err) {
    std::vector<std::size_t> never_started;
    std::vector<RunSession*> sessions;
    std::vector<std::size_t> runs;
    for (std::size_t m = 0; m < by_system.size(); ++m) {
        if (by_system[m] == nullptr) {
            never_started.push_back(m);
            continue;
        }
        sessions.push_back(by_system[m]);
        runs.push_back(run_of[m]);
    }
    if (name_runs)
        for (RunSession* session : sessions)
            session->name_in_messages();
    if (!sessions.empty()) {
        ensemble.retire(never_started);
        EnsembleLoop loop(ensemble, sessions, threads, style, out, err);
        const std::vector<int> ended = loop.run();
        for (std::size_t k = 0; k < runs.size(); ++k)
            codes[runs[k]] = ended[k];
    }
}

}  // namespace rodsea
