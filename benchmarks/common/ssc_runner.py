"""Running the ssc executable from the benchmark scripts, and reading what a
run wrote: the one helper every study folder's scripts share.

A script in benchmarks/<study>/ imports it with

    sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(
        os.path.abspath(__file__))), "common"))
    import ssc_runner  # noqa: E402

    run = ssc_runner.run(prm, {"Elasticity/Degree": 2}, output_dir=folder,
                         name="q2", ranks=2, timeout=900)
    if run.ok:
        summary = ssc_runner.read_summary(run.folder)

The executable is $SSC_BUILD_DIR/bin/ssc (build/bin/ssc of the repository
by default, as for ssc.sh). Overrides go to ssc as -s "Section/Name=value",
in the order given, after Run/Output directory and Run/Name. With ranks the
run goes through mpirun -np ranks, with mpirun allowed to run as root and,
unless bind is true, not binding the ranks to cores (as ssc.sh: two jobs at
once would otherwise share one core). run() returns the exit status, the
output, the wall time and the peak resident memory of the process; like
subprocess.run it raises subprocess.TimeoutExpired after timeout seconds
(the process killed) and, with check, subprocess.CalledProcessError on a
non-zero exit status.
"""
import csv
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time

# the repository: benchmarks/common/ is two levels below it
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))


def build_dir():
    """The build directory: $SSC_BUILD_DIR, else build/ of the repository."""
    return os.environ.get("SSC_BUILD_DIR", os.path.join(ROOT, "build"))


def ssc_executable():
    """The ssc executable of build_dir()."""
    return os.path.join(build_dir(), "bin", "ssc")


SSC = ssc_executable()


def settings(overrides):
    """The "Section/Name=value" strings of overrides: a dict (values are
    converted with str) or an iterable of such strings, order kept."""
    if isinstance(overrides, dict):
        return [f"{key}={value}" for key, value in overrides.items()]
    return list(overrides)


def command(prm, overrides=(), output_dir=None, name=None, ranks=None,
            ssc=None):
    """The command line of one ssc run of prm: mpirun -np ranks first if
    ranks is given (even 1), then -s Run/Output directory, -s Run/Name and
    -s for each override."""
    args = [ssc or SSC, prm]
    entries = []
    if output_dir is not None:
        entries.append(f"Run/Output directory={output_dir}")
    if name is not None:
        entries.append(f"Run/Name={name}")
    for entry in entries + settings(overrides):
        args += ["-s", entry]
    if ranks is not None:
        args = ["mpirun", "-np", str(ranks)] + args
    return args


def mpi_environment(env=None, bind=False):
    """env (default: this process's environment) with what mpirun needs:
    permission to run as root (CI runs as root) and, unless bind, no
    binding of the ranks to cores."""
    env = dict(os.environ if env is None else env,
               OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    if not bind:
        env["OMPI_MCA_hwloc_base_binding_policy"] = "none"
    return env


class Run:
    """One finished ssc process: args, returncode, stdout, stderr (text),
    wall_s (seconds from start to exit), max_rss_MB (peak resident memory
    of the process; of mpirun itself where it ran through mpirun) and
    folder (output_dir/name, None unless both were given)."""

    def __init__(self, args, returncode, stdout, stderr, wall_s, max_rss_MB,
                 folder):
        self.args, self.returncode = args, returncode
        self.stdout, self.stderr = stdout, stderr
        self.wall_s, self.max_rss_MB, self.folder = wall_s, max_rss_MB, folder

    @property
    def ok(self):
        return self.returncode == 0

    def summary(self):
        """The run's summary.json (folder must be known)."""
        return read_summary(self.folder)


def run(prm, overrides=(), output_dir=None, name=None, ranks=None, ssc=None,
        env=None, bind=False, timeout=None, check=False):
    """Runs ssc once on prm (see command() and mpi_environment()); env is
    the environment of the process (default: this one's, plus the mpirun
    settings where ranks is given). Returns a Run."""
    args = command(prm, overrides, output_dir, name, ranks, ssc)
    if ranks is not None:
        env = mpi_environment(env, bind)
    folder = os.path.join(output_dir, name) \
        if output_dir is not None and name is not None else None
    # the output goes to files, not pipes (nothing to drain while waiting),
    # and os.wait4 reaps the process with its resource usage
    with tempfile.TemporaryFile("w+") as out, \
            tempfile.TemporaryFile("w+") as err:
        start = time.perf_counter()
        process = subprocess.Popen(args, stdout=out, stderr=err, env=env,
                                   text=True)
        status, usage = _wait(process, timeout)
        wall = time.perf_counter() - start
        out.seek(0)
        err.seek(0)
        stdout, stderr = out.read(), err.read()
    if status is None:
        raise subprocess.TimeoutExpired(args, timeout, stdout, stderr)
    returncode = os.waitstatus_to_exitcode(status)
    if check and returncode != 0:
        raise subprocess.CalledProcessError(returncode, args, stdout, stderr)
    return Run(args, returncode, stdout, stderr, wall,
               usage.ru_maxrss / 1024, folder)


def _wait(process, timeout):
    """(wait status, resource usage) of process once it ends, or (None,
    None) if it was killed after timeout seconds; as subprocess.run, a
    timeout or an interrupt kills the process (SIGKILL)."""
    timer, killed = None, []
    if timeout is not None:
        def kill():
            killed.append(True)
            process.kill()
        timer = threading.Timer(timeout, kill)
        timer.start()
    try:
        _, status, usage = os.wait4(process.pid, 0)
    except BaseException:  # KeyboardInterrupt: do not leave it running
        process.kill()
        os.wait4(process.pid, 0)
        raise
    finally:
        if timer is not None:
            timer.cancel()
    # reaped by os.wait4, not by Popen: tell it, so it does not wait again
    process.returncode = os.waitstatus_to_exitcode(status)
    if killed and process.returncode == -signal.SIGKILL:
        return None, None
    return status, usage


def run_or_exit(label, prm, overrides=(), **options):
    """Runs ssc once on prm in a scratch folder (options as for run());
    returns its summary and its standard output, or stops the script
    naming label if the run failed."""
    with scratch() as tmp:
        result = run(prm, overrides, tmp, "run", **options)
        if not result.ok:
            sys.exit(f"{label}: failed: {result.stderr[-500:]}")
        return result.summary(), result.stdout


def read_summary(folder):
    """The summary.json a run wrote into its folder."""
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)


def layer_moduli(folder, layer="SAT"):
    """(E, nu) of layer in the parameters.prm a run wrote (every value it
    used, includes resolved)."""
    text = open(os.path.join(folder, "parameters.prm")).read()
    block = text[text.index(f"subsection {layer}\n"):]
    E = float(re.search(r"set Young's modulus\s*=\s*(\S+)", block).group(1))
    nu = float(re.search(r"set Poisson's ratio\s*=\s*(\S+)", block).group(1))
    return E, nu


def relaxed_layer_overrides(E, nu, shear_fraction, layers=("SAT", "DAT")):
    """Overrides that make a visco-elastic scene elastic, with no time and
    no Prony terms, its layers' shear modulus shear_fraction times that of
    (E, nu) and their bulk modulus unchanged: the elastic body of a
    visco-elastic one at a relaxed (or transformed) shear modulus."""
    mu, kappa = E / (2 * (1 + nu)), E / (3 * (1 - 2 * nu))
    mu_s = shear_fraction * mu
    overrides = {"Time/Loading history": "none"}
    for layer in layers:
        base = f"Layer stack/{layer}/"
        overrides[base + "Viscoelasticity/Relative moduli"] = ""
        overrides[base + "Viscoelasticity/Relaxation times"] = ""
        overrides[base + "Young's modulus"] = repr(
            9 * kappa * mu_s / (3 * kappa + mu_s))
        overrides[base + "Poisson's ratio"] = repr(
            (3 * kappa - 2 * mu_s) / (2 * (3 * kappa + mu_s)))
    return overrides


def read_table(folder, name="force_displacement.csv"):
    """The rows (dicts of strings) of a CSV file a run wrote."""
    with open(os.path.join(folder, name), newline="") as f:
        return list(csv.DictReader(f))


def write_rows(path, rows):
    """Writes rows (dicts with the same keys, in the order of the first)
    as a CSV file with a header line, and says so."""
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print("wrote", os.path.relpath(path, ROOT))


def keep(folder, destination, files=("summary.json",)):
    """Copies the named files of a run's folder into destination (created
    if missing), e.g. into a study's results/runs/<case>/."""
    os.makedirs(destination, exist_ok=True)
    for name in files:
        shutil.copy(os.path.join(folder, name), destination)


def remove(folder):
    """Deletes a run's folder (or a scratch directory), if it exists."""
    shutil.rmtree(folder, ignore_errors=True)


def scratch(prefix="ssc_"):
    """A scratch directory for run folders, deleted on leaving the with
    block: tempfile.TemporaryDirectory."""
    return tempfile.TemporaryDirectory(prefix=prefix)
