"""Running the chain: fem_tcl SCRIPT OUTDIR [args] -> fem2mpm -> mpm, with one error type for the drivers.

The FEM output contract (what a script run by `fem_tcl SCRIPT OUTDIR ...` must leave in OUTDIR):
    model.json   `print -JSON -file OUTDIR/model.json` after the model is built
    disp.out     `recorder Node -file OUTDIR/disp.out -time -nodeRange 1 N -dof 1 2 disp` (all nodes, tag order)
    vel.out      the same with `vel`
    stress.out   `recorder Element -file OUTDIR/stress.out -time -eleRange 1 M stress3D` (or `stress`)
and, optionally,
    loads.out    the same Node recorder with `unbalance`: the applied nodal loads (a surcharge), which the
                 particles then carry (fem2mpm --loads)
"""
import json
import os
import shutil
import subprocess
import sys
import time

FEM_OUTPUTS = ("model.json", "disp.out", "vel.out", "stress.out")
BINARIES = ("fem_tcl", "fem2mpm", "mpm")


class PipelineError(RuntimeError):
    """A stage failed or broke the contract; str() is the one-line message. bad_input: the input is at fault
    (a broken contract, or a program that exited with 2, its code for bad input)."""

    def __init__(self, message, bad_input=False, numerical=False):
        super().__init__(message)
        self.bad_input = bad_input
        self.numerical = numerical  # a program exited with 3, its code for a numerical failure

    def exit_code(self):
        """The driver's exit status for this failure: 2 bad input, 3 numerical failure, 1 otherwise."""
        return 2 if self.bad_input else 3 if self.numerical else 1


def find_bins(bin_dir, repo):
    """{name: path} of fem_tcl, fem2mpm and mpm in bin_dir (default REPO/build/bin); raises when missing."""
    d = bin_dir or os.path.join(repo, "build", "bin")
    bins = {k: os.path.join(d, k) for k in BINARIES}
    missing = [k for k, p in bins.items() if not os.access(p, os.X_OK)]
    if missing:
        raise PipelineError("%s not found in %s (build first: bash scripts/build.sh, or --bin DIR)" % (", ".join(missing), d))
    return bins


def run_cmd(cmd, cwd=None, logfile=None):
    """Runs cmd (stdout and stderr to logfile), returns wall seconds; raises PipelineError with the log's
    last line and the log's name as the message."""
    t0 = time.perf_counter()
    with open(logfile, "w") if logfile else open(os.devnull, "w") as f:
        r = subprocess.run(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT)
    wall = time.perf_counter() - t0
    if r.returncode != 0:
        tail = open(logfile).read()[-4000:] if logfile else ""
        last = [ln for ln in tail.splitlines() if ln.strip()]
        raise PipelineError("%s failed (exit %d): %s%s" % (os.path.basename(cmd[0]), r.returncode, last[-1] if last else "",
                                                          " (log: %s)" % logfile if logfile else ""),
                            bad_input=r.returncode == 2, numerical=r.returncode == 3)
    return wall


def log_warnings(logfile):
    """The warning lines a program wrote to its log ("prog: warning: ..."), in order; [] without a log."""
    if not logfile or not os.path.exists(logfile):
        return []
    with open(logfile, errors="replace") as f:
        return [ln.strip() for ln in f if "warning:" in ln]


def run_fem_script(bins, script, fem_dir, script_args=(), logfile=None):
    """fem_tcl SCRIPT FEM_DIR ARGS...; then checks the contract (check_fem_outputs). Returns wall seconds."""
    os.makedirs(fem_dir, exist_ok=True)
    wall = run_cmd([bins["fem_tcl"], script, fem_dir] + list(script_args), logfile=logfile or os.path.join(fem_dir, "fem_tcl.log"))
    check_fem_outputs(fem_dir, script)
    return wall


def check_fem_outputs(fem_dir, script="the FEM script"):
    """Raises PipelineError naming the first contracted file the script did not write (or left empty)."""
    for name in FEM_OUTPUTS:
        p = os.path.join(fem_dir, name)
        if not os.path.isfile(p) or os.path.getsize(p) == 0:
            raise PipelineError("%s did not write %s in its output folder (the first argument, %s); the contract: "
                                "model.json (print -JSON -file $out/model.json), disp.out and vel.out (recorder Node "
                                "-time ... disp|vel), stress.out (recorder Element -time ... stress3D)"
                                % (script, name, fem_dir), bad_input=True)


def remove_outputs(folder, names):
    """Removes what an earlier run left under these names in folder (files or folders), so that a failed run
    never leaves an older, complete-looking output behind."""
    for name in names:
        p = os.path.join(folder, name)
        if os.path.isdir(p):
            shutil.rmtree(p)
        elif os.path.exists(p):
            os.remove(p)


def fem2mpm_command(bins, fem_dir, out, t_transfer, options=()):
    """The fem2mpm command line on FEM_DIR's contracted files at time t_transfer into OUT."""
    return [bins["fem2mpm"], "--model", os.path.join(fem_dir, "model.json"), "--disp", os.path.join(fem_dir, "disp.out"),
            "--vel", os.path.join(fem_dir, "vel.out"), "--stress", os.path.join(fem_dir, "stress.out"),
            "--time", "%.10g" % t_transfer, "--out", out] + list(options)


# fem2mpm's options that need the pore pressures (bridge/README.md): with any of them the pore-pressure
# file the FEM run will write is part of the check
UP_OPTIONS = ("--liquefied", "--liquefied-table", "--residual-ratio", "--residual-n160cs", "--void-redistribution",
              "--liquefied-softening", "--reference-time", "--strain", "--pp-nodes", "--strength-step",
              "--max-liquefied-materials", "--effective-friction")


def check_fem2mpm_options(bins, fem_dir, out, t_transfer, options=()):
    """fem2mpm --check-options with the options run_fem2mpm will get: a bad option fails before the FEM
    analysis (raises PipelineError with fem2mpm's one-line message), not after it. The FEM files (and the
    pore-pressure file of a u-p model, given when a u-p option asks for it) need not exist yet."""
    cmd = fem2mpm_command(bins, fem_dir, out, t_transfer, options) + ["--check-options"]
    if any(w.split("=", 1)[0] in UP_OPTIONS for w in options) and "--pore-pressure" not in options:
        cmd += ["--pore-pressure", os.path.join(fem_dir, "pp.out")]
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, errors="replace")
    if r.returncode != 0:
        last = [ln for ln in r.stderr.splitlines() if ln.strip()]
        raise PipelineError("%s (checked before the FEM run)" % (last[-1] if last else "fem2mpm exit %d" % r.returncode),
                            bad_input=r.returncode == 2)


def run_fem2mpm(bins, fem_dir, out, t_transfer, options=(), logfile=None):
    """fem2mpm on FEM_DIR's contracted files at time t_transfer into OUT (its own options appended).
    Returns wall seconds; the log goes to OUT/fem2mpm.log."""
    cmd = fem2mpm_command(bins, fem_dir, out, t_transfer, options)
    if os.path.exists(os.path.join(fem_dir, "loads.out")):
        cmd += ["--loads", os.path.join(fem_dir, "loads.out")]
    if os.path.exists(os.path.join(fem_dir, "pp.out")) and "--pore-pressure" not in options:
        cmd += ["--pore-pressure", os.path.join(fem_dir, "pp.out")]
    parent = os.path.dirname(os.path.abspath(out))
    os.makedirs(parent, exist_ok=True)
    tmp_log = logfile or os.path.join(parent, os.path.basename(out) + "_fem2mpm.log")
    wall = run_cmd(cmd, logfile=tmp_log)
    if not logfile:
        os.replace(tmp_log, os.path.join(out, "fem2mpm.log"))
    return wall


def resume_file(deck_path, deck):
    """The particle file a resuming deck reads: <path>/<uuid>/particles<step>.h5, the step zero-padded to the
    digits of nsteps (CB-Geo's names; mpm/io/particle_table.cpp particle_file_name); None without a resume."""
    r = deck["analysis"].get("resume", {})
    if not r.get("resume"):
        return None
    digits = len(str(max(int(deck["analysis"]["nsteps"]), 1)))
    return os.path.join(os.path.dirname(os.path.abspath(deck_path)), deck.get("post_processing", {}).get("path", "results/"),
                        r["uuid"], "particles%0*d.h5" % (digits, int(r.get("step", 0))))


def edit_deck(deck_path, edit):
    """Loads mpm.json, calls edit(deck) and writes it back (write-then-rename). A resume file whose name
    changes with the edit (nsteps gaining or losing a digit) is renamed with it."""
    with open(deck_path) as f:
        deck = json.load(f)
    before = resume_file(deck_path, deck)
    edit(deck)
    after = resume_file(deck_path, deck)
    if before and after and before != after and os.path.exists(before):
        os.replace(before, after)
    tmp = deck_path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(deck, f, indent=2)
    os.replace(tmp, deck_path)
    return deck


def run_mpm(bins, work_dir, threads=1, deck="mpm.json"):
    """mpm -f WORK_DIR/ -i DECK --threads N; returns wall seconds (log in WORK_DIR/mpm.log)."""
    return run_cmd([bins["mpm"], "-f", work_dir.rstrip("/") + "/", "-i", deck, "--threads", str(threads)],
                   logfile=os.path.join(work_dir, "mpm.log"))


def results_dir(work_dir, deck="mpm.json"):
    """WORK_DIR/<post_processing.path>/<uuid> of a deck."""
    with open(os.path.join(work_dir, deck)) as f:
        d = json.load(f)
    uuid = d["analysis"].get("resume", {}).get("uuid") if d["analysis"].get("resume", {}).get("resume") else None
    uuid = uuid or d["analysis"].get("uuid") or os.path.splitext(deck)[0]
    return os.path.join(work_dir, d.get("post_processing", {}).get("path", "results/"), uuid)


def die(prog, message, code=2):
    """One line on stderr, exit code (2: bad input)."""
    print("%s: error: %s" % (prog, message), file=sys.stderr)
    sys.exit(code)


def split_words(prog, argv, own_options, refused=(), refused_why=""):
    """(own words, forwarded words, script words) of a driver's command line: `--` ends the options; the
    driver's own options (own_options: name -> whether it takes a value) with their values, and MODEL (the
    first word that is not an option or a value) are its own; the rest is forwarded. An option in `refused`
    is one line on stderr and exit 2 (refused_why says who sets it)."""
    script = []
    if "--" in argv:
        k = argv.index("--")
        argv, script = argv[:k], argv[k + 1:]
    own, forward, model_seen = [], [], False
    i = 0
    while i < len(argv):
        w = argv[i]
        name = w.split("=", 1)[0]
        if name in own_options:
            own.append(w)
            if own_options[name] and "=" not in w:
                if i + 1 >= len(argv) or argv[i + 1].startswith("--"):
                    die(prog, "option %s needs a value" % w)
                own.append(argv[i + 1])
                i += 1
        elif not w.startswith("-") and not model_seen and (not forward or not forward[-1].startswith("-")):
            own.append(w)
            model_seen = True
        else:
            if name in refused:
                die(prog, "option %s is set by %s" % (name, refused_why))
            forward.append(w)
        i += 1
    return own, forward, script
