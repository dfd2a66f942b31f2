#include "rodsea/campaign/slurm_executor.hpp"

#include <fcntl.h>
#include <pwd.h>
#include <sys/file.h>
#include <unistd.h>

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <ostream>
#include <set>
#include <sstream>
#include <vector>

#include "rodsea/cli/child_process.hpp"
#include "rodsea/cli/exit_codes.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/atomic_file.hpp"
#include "rodsea/number_text.hpp"

namespace rodsea {

namespace fs = std::filesystem;

namespace {

struct Captured {
    int exit_code = 127;
    std::string output, errors;  // what it printed on stdout, on stderr
};

// Runs a program found on PATH and captures what it prints.
Captured capture(const std::vector<std::string>& words) {
    std::ostringstream out, err;
    Captured c;
    c.exit_code = run_program(words, out, err);
    c.output = out.str();
    c.errors = err.str();
    return c;
}

bool on_path(const std::string& program) {
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path ? path : "");
    for (std::string dir; std::getline(dirs, dir, ':');)
        if (!dir.empty() && ::access((fs::path(dir) / program).c_str(), X_OK) == 0) return true;
    return false;
}

// A word for a bash script: single-quoted, so that spaces and `$` in paths stay literal.
std::string shell_word(const std::string& word) {
    std::string q = "'";
    for (const char c : word) {
        if (c == '\'')
            q += "'\\''";
        else
            q += c;
    }
    return q + "'";
}

std::string hms(long seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", seconds / 3600, seconds / 60 % 60,
                  seconds % 60);
    return text;
}

struct JobRecord {
    std::string kind;  // array or resubmit
    std::string id;
    int submission = 0;
};

fs::path slurm_dir(const CampaignPaths& paths) {
    return paths.dir / "slurm";
}
fs::path tasks_file(const CampaignPaths& paths, int k) {
    return slurm_dir(paths) / ("tasks-" + std::to_string(k) + ".txt");
}

std::vector<JobRecord> read_jobs(const CampaignPaths& paths) {
    std::vector<JobRecord> jobs;
    std::ifstream in(slurm_dir(paths) / "jobs.txt");
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        JobRecord r;
        if (words >> r.kind >> r.id >> r.submission) jobs.push_back(r);
    }
    return jobs;
}

void record_job(const CampaignPaths& paths, const JobRecord& r) {
    std::ofstream out(slurm_dir(paths) / "jobs.txt", std::ios::app);
    out << r.kind << " " << r.id << " " << r.submission << "\n";
    if (!out) throw FileError((slurm_dir(paths) / "jobs.txt").string(), "cannot be written");
}

// The job ids (array base ids) this user has in the queue, from squeue.
std::set<std::string> queued_jobs() {
    const passwd* user = ::getpwuid(::getuid());
    // COMPLETING is left out: a follow-up job (afterany) may start while its array's tasks are
    // still completing, and must then see their unfinished runs as free.
    const Captured c = capture({"squeue", "-h", "-o", "%F", "-t",
                                "PENDING,RUNNING,SUSPENDED,CONFIGURING,REQUEUED,RESIZING", "-u",
                                user ? user->pw_name : std::to_string(::getuid())});
    if (c.exit_code != 0)
        throw FileError("squeue", "failed (exit " + std::to_string(c.exit_code) + "): " + c.errors);
    // What is not a job id is not a queue: read as one, it would look empty and every run in it
    // would be submitted a second time.
    std::set<std::string> ids;
    std::istringstream lines(c.output);
    for (std::string id; lines >> id;) {
        if (id.find_first_not_of("0123456789") != std::string::npos)
            throw FileError("squeue", "printed '" + id.substr(0, 60) +
                                          "' where a job id belongs: its queue cannot be read, "
                                          "so nothing is submitted (run again once squeue works)");
        ids.insert(id);
    }
    return ids;
}

// The words, after the campaign file, that every command of this campaign repeats.
std::vector<std::string> campaign_words(const CampaignPaths& paths, const SlurmOptions& o) {
    std::vector<std::string> w{o.campaign_file.string(), "--out", fs::absolute(paths.dir).string()};
    if (o.scaling.scale != 1.0) w.insert(w.end(), {"--scale", exact_number(o.scaling.scale)});
    if (o.scaling.duration) w.insert(w.end(), {"--duration", exact_number(*o.scaling.duration)});
    return w;
}

// The options every task's runner and every follow-up submission pass on.
std::vector<std::string> executor_words(const SlurmOptions& o) {
    std::vector<std::string> w;
    if (o.retry_failed) w.push_back("--retry-failed");
    if (o.backend) w.insert(w.end(), {"--backend", to_string(*o.backend)});
    return w;
}

std::string command_line(const fs::path& executable, const std::vector<std::string>& words) {
    std::string line = "exec " + shell_word(executable.string());
    for (const std::string& w : words)
        line += " " + (w.front() == '"' ? w : shell_word(w));
    return line;
}

std::string sbatch_header(const std::string& job_name, const SlurmOptions& o,
                          const std::string& time, int cpus, const fs::path& log) {
    std::string h = "#SBATCH --job-name=" + job_name + "\n#SBATCH --time=" + time +
                    "\n#SBATCH --cpus-per-task=" + std::to_string(cpus) + "\n";
    if (!o.partition.empty()) h += "#SBATCH --partition=" + o.partition + "\n";
    if (!o.account.empty()) h += "#SBATCH --account=" + o.account + "\n";
    h += "#SBATCH --output=" + log.string() + "\n#SBATCH --open-mode=append\n";
    return h;
}

// Submits a script; returns the job id, or "" with sbatch's message in `message`.
std::string sbatch(const std::vector<std::string>& options, const fs::path& script,
                   std::string& message) {
    std::vector<std::string> words{"sbatch", "--parsable"};
    words.insert(words.end(), options.begin(), options.end());
    words.push_back(script.string());
    const Captured c = capture(words);
    message = c.errors + c.output;
    if (c.exit_code != 0) return "";
    // --parsable prints "id" or "id;cluster" on its standard output.
    std::istringstream lines(c.output);
    std::string id;
    for (std::string line; std::getline(lines, line);) {
        const std::string first = line.substr(0, line.find(';'));
        if (!first.empty() && first.find_first_not_of("0123456789") == std::string::npos)
            id = first;
    }
    if (id.empty()) message = "no job id in sbatch's answer:\n" + c.output;
    return id;
}

}  // namespace

long parse_slurm_time(const std::string& text) {
    const auto bad = [&]() -> long {
        throw InvalidParameter("--time", text.empty() ? "\"\"" : text,
                               "minutes, MM:SS, HH:MM:SS, D-HH, D-HH:MM or D-HH:MM:SS (as sbatch "
                               "--time), at least 1 minute",
                               "e.g. --time 12:00:00");
    };
    std::string rest = text;
    long days = 0;
    const std::size_t dash = rest.find('-');
    if (dash != std::string::npos) {
        const std::string day_text = rest.substr(0, dash);
        if (day_text.empty() || day_text.size() > 4 ||
            day_text.find_first_not_of("0123456789") != std::string::npos)
            return bad();
        days = std::stol(day_text);
        rest = rest.substr(dash + 1);
    }
    std::vector<long> parts;
    std::istringstream fields(rest);
    for (std::string f; std::getline(fields, f, ':');) {
        if (f.empty() || f.size() > 6 || f.find_first_not_of("0123456789") != std::string::npos)
            return bad();
        parts.push_back(std::stol(f));
    }
    if (text.find_first_not_of("0123456789:-") != std::string::npos || parts.empty() ||
        parts.size() > 3 || (dash != std::string::npos && dash == 0))
        return bad();
    long seconds = 0;
    if (dash != std::string::npos) {  // D-HH[:MM[:SS]]
        const long h = parts[0], m = parts.size() > 1 ? parts[1] : 0,
                   s = parts.size() > 2 ? parts[2] : 0;
        seconds = ((days * 24 + h) * 60 + m) * 60 + s;
    } else if (parts.size() == 1) {  // minutes
        seconds = parts[0] * 60;
    } else if (parts.size() == 2) {  // MM:SS
        seconds = parts[0] * 60 + parts[1];
    } else {
        seconds = (parts[0] * 60 + parts[1]) * 60 + parts[2];
    }
    if (seconds < 60 || seconds > 366L * 24 * 3600) return bad();
    return seconds;
}

std::vector<std::size_t> runs_of_task(const fs::path& file, long index, const CampaignGrid& grid) {
    std::ifstream in(file);
    if (!in) throw FileError(file.string(), "cannot be read (the --tasks file of a submission)");
    std::string line;
    long n = 0;
    bool found = false;
    for (std::string l; std::getline(in, l); ++n)
        if (n == index) {
            line = l;
            found = true;
        }
    if (!found || index < 0)
        throw InvalidParameter("--task", std::to_string(index),
                               "a task of " + file.string() + ": 0 to " + std::to_string(n - 1));
    std::vector<std::size_t> runs;
    std::istringstream ids(line);
    for (std::string id; std::getline(ids, id, '\t');) {
        std::size_t i = 0;
        while (i < grid.runs.size() && grid.runs[i].id != id)
            ++i;
        if (i == grid.runs.size())
            throw InvalidParameter(
                "--tasks", id,
                "a run of this campaign (" + file.string() + " task " + std::to_string(index) + ")",
                "the campaign file changed after it was submitted");
        runs.push_back(i);
    }
    return runs;
}

long check_slurm_options(const SlurmOptions& o) {
    if (!o.dry_run && !on_path("sbatch"))
        throw InvalidParameter("submit", "no sbatch on PATH",
                               "a machine with SLURM's commands (a cluster's login node)",
                               "--dry-run writes the script without submitting it");
    const long signal = o.signal_seconds.value_or(std::min<long>(300, o.time_seconds / 2));
    if (signal < 10 || signal >= o.time_seconds)
        throw InvalidParameter(
            "--signal-seconds", std::to_string(signal),
            "10 s or more and less than the wall time (" + std::to_string(o.time_seconds) + " s)");
    return signal;
}

int submit_campaign_to_slurm(const CampaignPaths& paths, const Campaign& campaign,
                             const CampaignGrid& grid, const SlurmOptions& o, std::ostream& out) {
    const long signal = check_slurm_options(o);
    const fs::path executable =
        fs::absolute(o.executable.empty() ? fs::read_symlink("/proc/self/exe") : o.executable);
    fs::create_directories(slurm_dir(paths) / "logs");

    // One submit at a time per campaign (a user's and a follow-up job's): each reads what the
    // other recorded.
    const fs::path lock_path = slurm_dir(paths) / "submit.lock";
    const int lock = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (lock < 0) throw FileError(lock_path.string(), "cannot be created");
    struct Unlock {
        int fd;
        ~Unlock() { ::close(fd); }
    } unlock{lock};
    if (::flock(lock, LOCK_EX) != 0) throw FileError(lock_path.string(), "cannot be locked");
    // What is queued already: runs of arrays still in the queue are theirs; a follow-up job
    // already queued will submit what is left, so this one need not.
    std::set<std::string> queued;
    if (!o.dry_run) queued = queued_jobs();
    const char* own = std::getenv("SLURM_JOB_ID");
    std::set<std::string> claimed;
    for (const JobRecord& r : read_jobs(paths)) {
        if (!queued.count(r.id) || (own && r.id == own)) continue;
        if (r.kind == "resubmit") {
            out << "submit: follow-up job " << r.id
                << " is queued and will submit what is left when the array before it ends; "
                   "nothing submitted (scancel "
                << r.id << " first to submit now)" << std::endl;
            return kExitOk;
        }
        std::ifstream tasks(tasks_file(paths, r.submission));
        for (std::string line; std::getline(tasks, line);) {
            std::istringstream ids(line);
            for (std::string id; std::getline(ids, id, '\t');)
                claimed.insert(id);
        }
    }

    const int max_failures = o.retry_failed ? 4 : 2;
    std::vector<std::string> to_submit;
    std::size_t done = 0, failed = 0, running = 0, in_queue = 0;
    for (const CampaignRun& r : grid.runs) {
        const RunState s = run_status(paths, r, max_failures).state;
        if (s == RunState::done)
            ++done;
        else if (s == RunState::failed)
            ++failed;
        else if (s == RunState::running)
            ++running;
        else if (claimed.count(r.id))
            ++in_queue;
        else
            to_submit.push_back(r.id);
    }
    out << "campaign " << campaign.name << ": " << grid.runs.size() << " runs: " << done
        << " done, " << running << " running, " << in_queue << " queued, " << failed << " failed, "
        << to_submit.size() << " to submit" << std::endl;
    if (failed)
        out << "submit: failed runs are left out (rodsea campaign status names them; "
               "--retry-failed gives them two more tries)"
            << std::endl;
    if (to_submit.empty()) {
        out << "submit: nothing to submit" << std::endl;
        return kExitOk;
    }

    int k = 1;
    while (fs::exists(tasks_file(paths, k)))
        ++k;
    std::string task_lines;
    const std::size_t tasks = (to_submit.size() + o.pack - 1) / o.pack;
    for (std::size_t t = 0; t < tasks; ++t) {
        for (std::size_t j = t * o.pack; j < std::min(to_submit.size(), (t + 1) * o.pack); ++j)
            task_lines += (j == t * o.pack ? "" : "\t") + to_submit[j];
        task_lines += "\n";
    }
    write_file_atomically(tasks_file(paths, k), task_lines);

    std::string name = "rodsea-" + campaign.name;
    for (char& ch : name)  // a job name is one word of letters, digits, '.', '_', '-'
        if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '.' && ch != '_' && ch != '-')
            ch = '_';
    const int threads = o.ensemble ? o.cpus_per_task : std::max(1, o.cpus_per_task / o.jobs);
    std::string array = "0-" + std::to_string(tasks - 1);
    if (o.throttle > 0) array += "%" + std::to_string(o.throttle);
    std::vector<std::string> task_words{"campaign", "run"};
    for (const std::string& w : campaign_words(paths, o))
        task_words.push_back(w);
    task_words.insert(task_words.end(), {"--tasks", fs::absolute(tasks_file(paths, k)).string(),
                                         "--task", "\"$SLURM_ARRAY_TASK_ID\""});
    if (o.ensemble)
        task_words.push_back("--ensemble");
    else
        task_words.insert(task_words.end(), {"--jobs", std::to_string(o.jobs)});
    task_words.insert(task_words.end(), {"--threads", std::to_string(threads)});
    for (const std::string& w : executor_words(o))
        task_words.push_back(w);
    const fs::path logs = fs::absolute(slurm_dir(paths) / "logs");
    std::string script = "#!/bin/bash\n# rodsea campaign " + name.substr(7) + ", submission " +
                         std::to_string(k) + ": " + std::to_string(to_submit.size()) + " runs in " +
                         std::to_string(tasks) + " array tasks (tasks-" + std::to_string(k) +
                         ".txt: one line per task). Written by `rodsea campaign submit`.\n"
                         "# SIGTERM " +
                         std::to_string(signal) +
                         " s before the wall time: every run writes its checkpoint and stops; "
                         "the next submission resumes it.\n";
    script += sbatch_header(name, o, o.time, o.cpus_per_task,
                            logs / ("array-" + std::to_string(k) + "_%a.out"));
    script +=
        "#SBATCH --array=" + array + "\n#SBATCH --signal=B:TERM@" + std::to_string(signal) + "\n";
    if (o.gpus_per_task > 0)
        script += "#SBATCH --gpus-per-task=" + std::to_string(o.gpus_per_task) + "\n";
    script += command_line(executable, task_words) + "\n";
    const fs::path array_script = slurm_dir(paths) / ("array-" + std::to_string(k) + ".sh");
    write_file_atomically(array_script, script);
    fs::permissions(array_script, fs::perms::owner_exec, fs::perm_options::add);

    const auto counted = [](std::size_t n, const std::string& noun) {
        return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
    };
    out << "submit: " << counted(to_submit.size(), "run") << " in " << counted(tasks, "array task")
        << " (" << counted(std::min<std::size_t>(o.pack, to_submit.size()), "run") << " each, "
        << (o.ensemble ? std::string("as one ensemble") : std::to_string(o.jobs) + " at a time")
        << " on " << counted(static_cast<std::size_t>(threads), "thread") << "); wall time "
        << hms(o.time_seconds) << ", " << counted(static_cast<std::size_t>(o.cpus_per_task), "CPU")
        << (o.gpus_per_task ? ", " + counted(static_cast<std::size_t>(o.gpus_per_task), "GPU") : "")
        << " per task; SIGTERM " << signal << " s before the end\n  script "
        << array_script.string() << std::endl;

    std::string resubmit_script;
    if (o.resubmit > 0) {
        std::vector<std::string> words{"campaign", "submit"};
        for (const std::string& w : campaign_words(paths, o))
            words.push_back(w);
        words.insert(words.end(), {"--time", o.time, "--signal-seconds", std::to_string(signal),
                                   "--cpus-per-task", std::to_string(o.cpus_per_task),
                                   "--gpus-per-task", std::to_string(o.gpus_per_task), "--throttle",
                                   std::to_string(o.throttle), "--pack", std::to_string(o.pack),
                                   "--resubmit", std::to_string(o.resubmit - 1)});
        if (o.ensemble)
            words.push_back("--ensemble");
        else
            words.insert(words.end(), {"--jobs", std::to_string(o.jobs)});
        if (!o.partition.empty()) words.insert(words.end(), {"--partition", o.partition});
        if (!o.account.empty()) words.insert(words.end(), {"--account", o.account});
        for (const std::string& w : executor_words(o))
            words.push_back(w);
        std::string text = "#!/bin/bash\n# rodsea campaign " + name.substr(7) +
                           ": submits what submission " + std::to_string(k) +
                           " left unfinished, once its array has ended (" +
                           std::to_string(o.resubmit - 1) + " more follow-ups after this).\n";
        text += sbatch_header(name + "-resubmit", o, "10:00", 1,
                              logs / ("resubmit-" + std::to_string(k) + ".out"));
        text += command_line(executable, words) + "\n";
        const fs::path path = slurm_dir(paths) / ("resubmit-" + std::to_string(k) + ".sh");
        write_file_atomically(path, text);
        fs::permissions(path, fs::perms::owner_exec, fs::perm_options::add);
        resubmit_script = path.string();
    }

    if (o.dry_run) {
        out << "submit: dry run, nothing submitted; `sbatch " << array_script.string()
            << "` submits it (an array submitted by hand is not recorded in jobs.txt: a later "
               "submit may take its runs too, and the locks then keep each run to one task)";
        if (!resubmit_script.empty())
            out << ", then `sbatch --dependency=afterany:<its job id> " << resubmit_script
                << "` the follow-up";
        out << std::endl;
        return kExitOk;
    }
    std::string message;
    const std::string id = sbatch({}, array_script, message);
    if (id.empty()) {
        out << "submit: sbatch refused " << array_script.string() << ":\n" << message << std::endl;
        return kExitFailure;
    }
    record_job(paths, {"array", id, k});
    out << "submit: job array " << id << " (tasks " << array << ")" << std::endl;
    if (!resubmit_script.empty()) {
        const std::string follow =
            sbatch({"--dependency=afterany:" + id}, resubmit_script, message);
        if (follow.empty()) {
            out << "submit: sbatch refused the follow-up " << resubmit_script << ":\n"
                << message << "\nsubmit: run `rodsea campaign submit` again when job " << id
                << " has ended" << std::endl;
            return kExitFailure;
        }
        record_job(paths, {"resubmit", follow, k});
        out << "submit: follow-up job " << follow << " submits what is left when " << id
            << " ends (" << o.resubmit << " follow-up" << (o.resubmit > 1 ? "s" : "") << " at most)"
            << std::endl;
    }
    return kExitOk;
}

}  // namespace rodsea
