#pragma once
// A one-node SLURM cluster on localhost for a test: Debian's munged, slurmctld and slurmd run as
// root from a temporary directory (own munge key and socket, own ports, no system file touched)
// and are stopped, with every job cancelled, when the object goes. `unavailable()` says why a
// cluster cannot be started here (not root, packages missing), for GTEST_SKIP.
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <thread>

#include "child_process.hpp"

namespace rodsea {

class LocalSlurmCluster {
  public:
    static std::optional<std::string> unavailable() {
        if (::geteuid() != 0)
            return "not root: slurmd must run as root to start jobs (CI runs as root)";
        for (const char* program : {"/usr/sbin/munged", "/usr/sbin/slurmctld", "/usr/sbin/slurmd",
                                    "/usr/bin/sbatch", "/usr/bin/squeue", "/usr/bin/sinfo"})
            if (::access(program, X_OK) != 0)
                return std::string(program) +
                       " missing: scripts/install-deps.sh installs munge, slurmctld, slurmd and "
                       "slurm-client";
        return std::nullopt;
    }

    explicit LocalSlurmCluster(const std::filesystem::path& dir) : dir_(dir) {
        namespace fs = std::filesystem;
        for (const char* sub : {"munge", "state", "spool", "log"})
            fs::create_directories(dir_ / sub);
        fs::permissions(dir_ / "munge", fs::perms::owner_all);
        {
            std::ifstream random("/dev/urandom", std::ios::binary);
            std::string key(1024, '\0');
            random.read(key.data(), static_cast<std::streamsize>(key.size()));
            std::ofstream(dir_ / "munge" / "munge.key", std::ios::binary) << key;
        }
        fs::permissions(dir_ / "munge" / "munge.key", fs::perms::owner_read);
        const std::string d = dir_.string();
        std::ofstream(dir_ / "slurm.conf")
            << "ClusterName=rodseatest\nSlurmctldHost=localhost(127.0.0.1)\n"
               "SlurmctldPort=16817\nSlurmdPort=16818\nSlurmUser=root\nSlurmdUser=root\n"
               "AuthType=auth/munge\nCredType=cred/munge\nAuthInfo=socket="
            << d << "/munge/munge.socket\nStateSaveLocation=" << d << "/state\nSlurmdSpoolDir=" << d
            << "/spool\nSlurmctldPidFile=" << d << "/slurmctld.pid\nSlurmdPidFile=" << d
            << "/slurmd.pid\nSlurmctldLogFile=" << d << "/log/slurmctld.log\nSlurmdLogFile=" << d
            << "/log/slurmd.log\n"
               "ProctrackType=proctrack/linuxproc\nTaskPlugin=task/none\n"
               "SelectType=select/cons_tres\nSelectTypeParameters=CR_CPU\n"
               "SchedulerType=sched/builtin\nMpiDefault=none\nReturnToService=2\n"
               "JobCompType=jobcomp/none\nAccountingStorageType=accounting_storage/none\n"
               "JobAcctGatherType=jobacct_gather/none\nMinJobAge=30\nKillWait=10\n"
               "InactiveLimit=0\nSlurmctldTimeout=30\nSlurmdTimeout=30\n"
               "NodeName=rodseanode NodeHostname=localhost NodeAddr=127.0.0.1 CPUs=2 "
               "RealMemory=1000 State=UNKNOWN\n"
               "PartitionName=test Nodes=rodseanode Default=YES MaxTime=INFINITE State=UP\n";
        // sbatch, squeue and the jobs (which inherit the environment) find this cluster.
        ::setenv("SLURM_CONF", (dir_ / "slurm.conf").c_str(), 1);
        started_ = true;
        shell("/usr/sbin/munged --force --key-file=" + d + "/munge/munge.key --socket=" + d +
              "/munge/munge.socket --pid-file=" + d + "/munge/munged.pid --log-file=" + d +
              "/log/munged.log --seed-file=" + d + "/munge/seed");
        shell("/usr/sbin/slurmctld -c -i -f " + d + "/slurm.conf");
        shell("/usr/sbin/slurmd -N rodseanode -f " + d + "/slurm.conf");
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
        while (std::chrono::steady_clock::now() < deadline) {
            if (shell_output("sinfo -h -o %T 2>/dev/null").find("idle") != std::string::npos) {
                ready_ = true;
                break;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(500));
        }
    }

    ~LocalSlurmCluster() {
        if (!started_) return;
        shell("scancel --full -u root >/dev/null 2>&1");
        std::this_thread::sleep_for(std::chrono::seconds(1));
        for (const char* pid : {"slurmd.pid", "slurmctld.pid", "munge/munged.pid"})
            shell("kill $(cat " + (dir_ / pid).string() + " 2>/dev/null) 2>/dev/null");
        std::this_thread::sleep_for(std::chrono::seconds(1));
        ::unsetenv("SLURM_CONF");
    }
    LocalSlurmCluster(const LocalSlurmCluster&) = delete;
    LocalSlurmCluster& operator=(const LocalSlurmCluster&) = delete;

    bool ready() const { return ready_; }
    std::string logs() const {
        return shell_output("tail -n 30 " + (dir_ / "log" / "slurmctld.log").string() + " " +
                            (dir_ / "log" / "slurmd.log").string() + " 2>&1");
    }
    bool queue_empty() const { return shell_output("squeue -h 2>&1").empty(); }

  private:
    static void shell(const std::string& command) {
        [[maybe_unused]] const int status = std::system(command.c_str());
    }

    std::filesystem::path dir_;
    bool started_ = false, ready_ = false;
};

}  // namespace rodsea
