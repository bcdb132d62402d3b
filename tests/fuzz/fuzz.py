#!/usr/bin/env python3
"""Mutation-based fuzzing of the three programs (issue 11).

Each target takes seed inputs from the project's own test data, mutates them (tokens replaced by
hostile numbers such as nan, inf, 1e400, -1, 0, huge integers; words, lines and bytes deleted,
duplicated, swapped, truncated or replaced by binary garbage; HDF5 fields set to nan/inf and row counts
inflated), runs the program in a fresh folder with a time limit, and classifies the outcome:

  success       exit 0, outputs complete and finite
  clean error   exit 1, 2 or 3 with a one-line printable message (fem_tcl: the last line)
  unclear error exit 1, 2 or 3 but an empty, multi-line (warning lines before the error line aside) or non-printable message
  crash         a signal, a sanitizer report, or any other exit status
  hang          the time limit was reached
  non-finite    exit 0 but an output holds nan/inf (or JSON null where a number belongs)
  half-written  a *.tmp.<pid> file left behind, an output that does not parse, or outputs written by a
                run that failed (fem2mpm promises nothing is written on error)

Targets: tcl (fem_tcl scripts), fem2mpm (recorder files, model JSON, options), mpm (CB-Geo JSON,
mesh, particle and entity-set files), hdf5 (the particle /table read on resume, and the /friction_memory and /apic_affine beside it).

  smoke run (CI, ctest -L fuzz):  tests/fuzz/fuzz.py --bin build-asan/bin --cases 75
  long run:                        tests/fuzz/fuzz.py --bin build-asan/bin --cases 10000 --jobs 2

Exit status 1 when any case crashed, hung, wrote non-finite output or a half-written file; the
failing inputs are kept under --keep (default: <work>/failures).
"""
import argparse
import concurrent.futures
import json
import math
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "data" / "reference_runs"
OPENSEES = DATA / "opensees"
CBGEO = DATA / "cbgeo"
BRIDGE_CASE = OPENSEES / "sspquad_block_surface_load" / "ref"

HOSTILE_NUMBERS = ["nan", "-nan", "inf", "-inf", "1e400", "-1e400", "1e308", "-1e308", "1e-320", "0", "-0", "-1",
                   "1", "2", "0.5", "999999999", "-999999999", "9223372036854775808", "4294967296", "1e12", "3.5",
                   "abc", "", "0x10", "1e", "--", "NaN", "Infinity"]
GARBAGE = [b"\x00", b"\xff\xfe", b"\x1b[31m", b"\x01\x02\x03", b"\xc3", b"{", b"}", b"[", b"\"", b"\\", b"#", b"!",
           b"\n", b"\t", b"$x", b"[expr 1/0]"]
NUMBER_RE = re.compile(rb"-?\d+(\.\d+)?([eE][-+]?\d+)?")
OUTCOMES = ["success", "clean error", "unclear error", "crash", "hang", "non-finite", "half-written"]
BAD = {"crash", "hang", "non-finite", "half-written", "unclear error"}
SANITIZER_MARKS = ("AddressSanitizer", "runtime error:", "LeakSanitizer", "UndefinedBehaviorSanitizer")


# ------------------------------------------------------------------------------------------ mutations

def mutate_text(data: bytes, rng: random.Random, rounds: int = None) -> bytes:
    """Token- and line-level mutations of a text input (several rounds)."""
    rounds = rounds or rng.choice([1, 1, 1, 2, 3])
    for _ in range(rounds):
        op = rng.randrange(9)
        if op <= 2:  # replace a number by a hostile one (the most productive mutation)
            matches = list(NUMBER_RE.finditer(data))
            if matches:
                m = rng.choice(matches)
                data = data[:m.start()] + rng.choice(HOSTILE_NUMBERS).encode() + data[m.end():]
                continue
        lines = data.split(b"\n")
        if op == 3 and len(lines) > 1:  # delete a line
            del lines[rng.randrange(len(lines))]
        elif op == 4:  # duplicate a line
            k = rng.randrange(len(lines))
            lines.insert(k, lines[k])
        elif op == 5 and len(lines) > 1:  # swap two lines
            a, b = rng.randrange(len(lines)), rng.randrange(len(lines))
            lines[a], lines[b] = lines[b], lines[a]
        elif op == 6:  # truncate anywhere (a cut file)
            data = data[:rng.randrange(len(data) + 1)]
            continue
        elif op == 7:  # insert garbage bytes
            at = rng.randrange(len(data) + 1)
            data = data[:at] + rng.choice(GARBAGE) + data[at:]
            continue
        else:  # delete or duplicate a word
            k = rng.randrange(len(lines))
            words = lines[k].split(b" ")
            if words:
                w = rng.randrange(len(words))
                if rng.random() < 0.5:
                    del words[w]
                else:
                    words.insert(w, words[w])
                lines[k] = b" ".join(words)
        data = b"\n".join(lines)
    return data


def mutate_binary(data: bytes, rng: random.Random) -> bytes:
    data = bytearray(data)
    op = rng.randrange(4)
    if op == 0 and data:  # flip bytes
        for _ in range(rng.randint(1, 8)):
            data[rng.randrange(len(data))] = rng.randrange(256)
    elif op == 1:  # truncate
        del data[rng.randrange(len(data) + 1):]
    elif op == 2 and data:  # overwrite a block with garbage
        at = rng.randrange(len(data))
        n = rng.randint(1, 64)
        data[at:at + n] = bytes(rng.randrange(256) for _ in range(n))
    else:  # zero a block
        at = rng.randrange(len(data) + 1)
        data[at:at + 512] = bytes(min(512, len(data) - at))
    return bytes(data)


# ------------------------------------------------------------------------------------------ checking

def message_is_clean(err: bytes, last_line_only: bool) -> bool:
    lines = [l for l in err.split(b"\n") if l.strip()]
    if not lines:
        return False
    # warnings before the error line ("mpm: warning: analysis.dt ... above the elastic limit") are not the error
    lines = [l for l in lines[:-1] if b": warning: " not in l] + lines[-1:]
    if not last_line_only and len(lines) != 1:
        return False
    try:  # valid UTF-8 without control characters (common::printable escapes everything else)
        text = lines[-1].decode("utf-8")
    except UnicodeDecodeError:
        return False
    return not any(ord(c) < 32 or 0x7f <= ord(c) < 0xa0 for c in text)


NONFINITE_RE = re.compile(rb"(?<![A-Za-z_])(-?nan|-?inf|infinity)(?![A-Za-z_])", re.IGNORECASE)


def text_non_finite(path: Path) -> bool:
    return bool(NONFINITE_RE.search(path.read_bytes()))


# series.csv columns that mpm/README.md documents as NaN when undefined (no particles, no gravity)
DOCUMENTED_NAN_COLUMNS = {"runout_x_p98", "height_y_p995", "checkerboard_index"}


def csv_non_finite(path: Path) -> bool:
    lines = path.read_text(errors="replace").splitlines()
    if not lines:
        return False
    names = lines[0].split(",")
    for line in lines[1:]:
        for name, value in zip(names, line.split(",")):
            if name not in DOCUMENTED_NAN_COLUMNS and NONFINITE_RE.fullmatch(value.strip().encode()):
                return True
    return False


def json_problem(path: Path):
    """'half-written' when the JSON does not parse, 'non-finite' when it holds null."""
    try:
        text = path.read_text()
        json.loads(text)
    except Exception:
        return "half-written"
    if re.search(r":\s*null|\[\s*null|,\s*null", text):
        return "non-finite"
    return None


def h5_problem(path: Path):
    try:
        import h5py
        import numpy as np
    except ImportError:
        return None
    # A particle file holds CB-Geo's /table; mpm's initial_state.h5 (the first ParaView frame, a view
    # and not a restart file) holds only the /xdmf arrays.
    try:
        with h5py.File(path, "r") as f:
            if "table" in f:
                table = f["table"][...]
                columns = [table[name] for name in table.dtype.names]
            else:
                columns = [f["xdmf"][name][...] for name in f["xdmf"]]
    except Exception:
        return "half-written"
    for col in columns:
        if col.dtype.kind == "f" and not np.isfinite(col).all():
            return "non-finite"
    return None


def check_outputs(folder: Path, since: float, inputs: set):
    """Worst problem among the files written in `folder` (after `since`), or None."""
    problem = None
    for p in folder.rglob("*"):
        if not p.is_file() or p.name in ("stdout.txt", "stderr.txt"):
            continue
        if ".tmp." in p.name:
            return "half-written"
        if p in inputs or p.stat().st_mtime < since:
            continue
        found = None
        if p.suffix == ".json":
            found = json_problem(p)
        elif p.suffix == ".h5":
            found = h5_problem(p)
        elif p.suffix == ".csv":
            found = "non-finite" if csv_non_finite(p) else None
        elif p.suffix in (".out", ".txt", ".xdmf"):
            found = "non-finite" if text_non_finite(p) else None
        if found == "half-written":
            return found
        problem = problem or found
    return problem


def tmp_left(folder: Path) -> bool:
    return any(".tmp." in p.name for p in folder.rglob("*"))


def classify(proc_rc, err: bytes, folder: Path, since: float, inputs: set, last_line_only: bool,
             must_write_nothing_on_error: Path = None) -> str:
    if proc_rc is None:
        return "hang"
    if any(m.encode() in err for m in SANITIZER_MARKS) or proc_rc < 0 or proc_rc not in (0, 1, 2, 3):
        return "crash"
    if proc_rc == 0:
        return check_outputs(folder, since, inputs) or "success"
    if tmp_left(folder):
        return "half-written"
    if must_write_nothing_on_error is not None and must_write_nothing_on_error.exists() and \
            any(p.is_file() for p in must_write_nothing_on_error.rglob("*")):
        return "half-written"
    return "clean error" if message_is_clean(err, last_line_only) else "unclear error"


def run(cmd, cwd: Path, timeout: float):
    env = dict(os.environ, OMP_NUM_THREADS="1", OMP_WAIT_POLICY="passive")
    try:
        p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, timeout=timeout, env=env,
                           stdin=subprocess.DEVNULL)
        return p.returncode, p.stderr
    except subprocess.TimeoutExpired as e:
        return None, e.stderr or b""


# ------------------------------------------------------------------------------------------ targets

def tcl_seeds():
    seeds = []
    for d in sorted(OPENSEES.iterdir()):
        if (d / "model.tcl").exists():
            seeds.append((d / "model.tcl").read_bytes())
    return seeds


# A long valid analysis is not a hang: a step budget, prepended to every mutated script on one line (the
# script's own lines move down by one). Each `analyze N` call runs at most 50 steps, and once 300 steps have run
# in all (the liquefiable column's `analyze $n` is 1,600 steps, the DSS scripts loop on `analyze 1`) the script
# ends as `exit 0` would, its recorders flushed. A step count that is not a positive integer goes to the real
# command unchanged, which reports it.
STEP_BUDGET = (b"set fuzz_steps_left 300; rename analyze fuzz_analyze; proc analyze {args} { global fuzz_steps_left; "
               b"set n [lindex $args 0]; if {[string is integer -strict $n] && $n > 0} { "
               b"if {$fuzz_steps_left <= 0} { exit 0 }; set n [expr {min($n, 50, $fuzz_steps_left)}]; "
               b"incr fuzz_steps_left -$n; lset args 0 $n }; uplevel 1 [list fuzz_analyze {*}$args] }\n")


def case_tcl(rng, folder: Path, bins: Path, seeds, timeout):
    script = STEP_BUDGET + mutate_text(rng.choice(seeds["tcl"]), rng)
    (folder / "model.tcl").write_bytes(script)
    inputs = {folder / "model.tcl"}
    since = time.time() - 1
    rc, err = run([str(bins / "fem_tcl"), "model.tcl"], folder, timeout)
    return classify(rc, err, folder, since, inputs, last_line_only=True)


FEM2MPM_OPTIONS = ["--time", "--row", "--nodes", "--elements", "--E", "--nu", "--density", "--phi", "--cohesion", "--psi",
                   "--tension", "--gravity", "--ppd", "--cell-size", "--base-friction", "--base-y", "--dt", "--cfl",
                   "--duration", "--nsteps", "--output-steps", "--damping", "--step", "--uuid", "--extent"]


def case_fem2mpm(rng, folder: Path, bins: Path, seeds, timeout):
    files = {"model.json": BRIDGE_CASE / "model.json", "disp.out": BRIDGE_CASE / "disp.out",
             "stress.out": BRIDGE_CASE / "stress.out"}
    with_loads = rng.random() < 0.3  # the displacement file's layout read as nodal loads (--loads)
    if with_loads:
        files["loads.out"] = BRIDGE_CASE / "disp.out"
    target = rng.choice(list(files) + ["options", "options"])
    for name, src in files.items():
        data = src.read_bytes()
        if name == target:
            data = mutate_text(data, rng)
        (folder / name).write_bytes(data)
    args = ["--model", "model.json", "--disp", "disp.out", "--stress", "stress.out", "--units", "kN", "--out", "deck",
            "--quiet", "--nsteps", "3"]
    if with_loads:
        args += ["--loads", "loads.out"]
    if rng.random() < 0.5:
        args += ["--material-type", "mohr-coulomb", "--phi", "30", "--cohesion", "5"]
    if target == "options":
        for _ in range(rng.randint(1, 3)):
            opt = rng.choice(FEM2MPM_OPTIONS)
            values = [rng.choice(HOSTILE_NUMBERS) for _ in range(4 if opt == "--extent" else 1)]
            if opt in ("--nodes", "--elements") and rng.random() < 0.5:
                values = [f"{rng.choice(HOSTILE_NUMBERS)}-{rng.choice(HOSTILE_NUMBERS)}"]
            args += [opt] + values
    inputs = {folder / n for n in files}
    since = time.time() - 1
    rc, err = run([str(bins / "fem2mpm")] + args, folder, timeout)
    return classify(rc, err, folder, since, inputs, last_line_only=False, must_write_nothing_on_error=folder / "deck")


def limit_steps(deck: dict):
    """Keeps a mutated deck short (a long valid run is not a hang)."""
    a = deck.get("analysis") if isinstance(deck, dict) else None
    if isinstance(a, dict) and isinstance(a.get("nsteps"), int) and not isinstance(a.get("nsteps"), bool):
        r = a.get("resume")
        resume = isinstance(r, dict) and r.get("resume") is True
        # the resume file's name has int(log10(nsteps)) + 1 digits: keep that many
        short = max(30, 10 ** int(math.log10(a["nsteps"]))) if resume and a["nsteps"] > 0 else 30
        if a["nsteps"] > short:
            a["nsteps"] = short
            if isinstance(r, dict) and isinstance(r.get("step"), int) and r["step"] >= short:
                r["step"] = 0
        pp = deck.get("post_processing")
        if isinstance(pp, dict) and isinstance(pp.get("output_steps"), int) and pp["output_steps"] > 10:
            pp["output_steps"] = 10


def mutate_json_values(obj, rng):
    """Replaces one leaf of a JSON document by a hostile value (structure-aware)."""
    leaves = []

    def walk(o, parent, key):
        if isinstance(o, dict):
            for k, v in o.items():
                walk(v, o, k)
        elif isinstance(o, list):
            for i, v in enumerate(o):
                walk(v, o, i)
        else:
            leaves.append((parent, key))
    walk(obj, None, None)
    if not leaves:
        return obj
    parent, key = rng.choice(leaves)
    parent[key] = rng.choice([float("nan"), float("inf"), -1, 0, 1e308, 10**19, -10**19, 2**31, "x", None, True, [],
                              {}, 1e-300, 0.5, "../..", "a/b", "\u0001"])
    return obj


def copy_case(name: str, folder: Path):
    src = CBGEO / name
    for p in src.iterdir():
        if p.name == "ref":
            continue
        if p.is_dir():
            shutil.copytree(p, folder / p.name)
        else:
            shutil.copy(p, folder / p.name)


def add_loads(deck: dict):
    """CB-Geo's loads besides gravity, so that mutations reach their reader and the engine's load paths: a
    Sin and a Linear math function, nodal forces and particle tractions on every node and particle."""
    deck["math_functions"] = [{"id": 0, "type": "Sin", "a": 5.0, "x0": 0.0, "xrange": [0.0, 10.0]},
                              {"id": 1, "type": "Linear", "xvalues": [0.0, 1.0], "fxvalues": [0.0, 1.0]}]
    loads = deck.setdefault("external_loading_conditions", {"gravity": [0.0, -9.81]})
    loads["concentrated_nodal_forces"] = [{"nset_id": -1, "dir": 1, "force": -1.0, "math_function_id": 1}]
    loads["particle_surface_traction"] = [{"pset_id": -1, "dir": 0, "traction": 10.0, "math_function_id": 0}]


def add_normal_lag(deck: dict):
    """This mpm's lagged friction strength (friction_constraints[].normal_lag) on every friction constraint, so
    that mutations reach its reader and the engine's lagged friction."""
    bc = deck.get("mesh", {}).get("boundary_conditions", {})
    for c in bc.get("friction_constraints", []):
        if isinstance(c, dict):
            c["normal_lag"] = {"slip_distance": 0.1, "reference_velocity": 1.0}


def prepare_deck(folder: Path, rng, mutate_json: bool):
    deck = json.loads((folder / "mpm.json").read_text())
    if rng.random() < 0.3:
        add_loads(deck)
    if rng.random() < 0.3:
        add_normal_lag(deck)
    limit_steps(deck)
    text = json.dumps(deck, indent=1)
    if mutate_json:
        if rng.random() < 0.5:
            deck = mutate_json_values(deck, rng)
            limit_steps(deck)
            text = json.dumps(deck, indent=1)  # nan/inf become NaN/Infinity: not JSON, as a user could write
        else:
            text = mutate_text(text.encode(), rng).decode("utf-8", "surrogateescape")
            try:
                d = json.loads(text)
                limit_steps(d)
                text = json.dumps(d, indent=1)
            except Exception:
                pass
    (folder / "mpm.json").write_text(text, errors="surrogateescape")


def case_mpm(rng, folder: Path, bins: Path, seeds, timeout):
    name = rng.choice(["elastic_block_drop", "mc_column_gimp_short", "resume_from_h5"])
    copy_case(name, folder)
    target = rng.choice(["mpm.json", "mpm.json", "mesh.txt", "particles.txt", "entity_sets.json", "particles-stresses.txt"])
    prepare_deck(folder, rng, target == "mpm.json")
    if target != "mpm.json" and (folder / target).exists():
        (folder / target).write_bytes(mutate_text((folder / target).read_bytes(), rng))
    inputs = {p for p in folder.rglob("*") if p.is_file()}
    since = time.time() + 0.0
    time.sleep(0.01)
    rc, err = run([str(bins / "mpm"), "-f", str(folder) + "/", "-i", "mpm.json", "--threads", "1"], folder, timeout)
    return classify(rc, err, folder, since, inputs, last_line_only=False)


def add_resume_extras(folder: Path, h5: Path, rng):
    """The datasets mpm reads beside /table (mpm/io/resume_extras.hpp), with the deck keys that make it read
    them: /friction_memory for a lagged base friction on node set 0, /apic_affine for the APIC transfer, and
    /pore_pressure (read whenever present); each of a valid shape with odd values, or of an odd shape or type."""
    import h5py
    import numpy as np
    deck = json.loads((folder / "mpm.json").read_text())
    deck["mesh"].setdefault("boundary_conditions", {})["friction_constraints"] = [
        {"nset_id": 0, "dir": 1, "sign_n": -1, "friction": 0.3,
         "normal_lag": {"slip_distance": 0.1, "reference_velocity": 1.0}}]
    apic = rng.random() < 0.5
    if apic:
        deck["analysis"].pop("velocity_update", None)
        deck["analysis"]["transfer"] = "apic"
    (folder / "mpm.json").write_text(json.dumps(deck, indent=1))
    nodes = json.loads((folder / "entity_sets.json").read_text())["node_sets"][0]["set"]
    odd = [np.nan, np.inf, -1.0, 0.0, 1e308, 1e-320, 0.5, 2.0**60]
    with h5py.File(h5, "r+") as f:
        rows = len(f["table"])
        shapes = {"friction_memory": [(rng.choice([0, 1, 3, 9]), 3), (2, 2), (3,), (1, 4)],
                  "apic_affine": [(rows, 4), (rows + 1, 4), (rows, 3), (rows,)],
                  "pore_pressure": [(rows, 3), (rows - 1, 3), (rows, 4), (rows,)]}
        for name in (["friction_memory"] + (["apic_affine"] if apic else []) +
                     (["pore_pressure"] if rng.random() < 0.5 else [])):
            shape = rng.choice(shapes[name]) if rng.random() < 0.3 else shapes[name][0]
            data = np.zeros(shape)
            if name == "friction_memory" and len(shape) == 2 and shape[1] == 3:
                for r in range(shape[0]):
                    data[r] = [rng.choice(nodes), rng.uniform(0, 1e4), rng.uniform(1e-3, 10)]
            flat = data.reshape(-1)
            for _ in range(rng.choice([0, 1, 2]) if flat.size else 0):
                flat[rng.randrange(flat.size)] = rng.choice(odd)
            dtype = rng.choice(["f8", "f8", "f4", "i4"])
            with np.errstate(invalid="ignore", over="ignore"):  # nan and 1e308 as i4 / f4: odd on purpose
                f.create_dataset(name, data=data.astype(dtype))


def case_hdf5(rng, folder: Path, bins: Path, seeds, timeout):
    copy_case("resume_from_h5", folder)
    prepare_deck(folder, rng, False)
    h5 = next((folder / "results").rglob("*.h5"))
    if rng.random() < 0.3:
        try:
            add_resume_extras(folder, h5, rng)
        except ImportError:
            pass
    if rng.random() < 0.5:
        h5.write_bytes(mutate_binary(h5.read_bytes(), rng))
    else:
        try:
            import h5py
            import numpy as np
            with h5py.File(h5, "r+") as f:
                d = f["table"]
                if rng.random() < 0.3 and d.maxshape[0] is None:
                    d.resize((rng.choice([0, 1, 10**6, 10**12]),))
                else:
                    t = d[...]
                    name = rng.choice(t.dtype.names)
                    i = rng.randrange(len(t))
                    if t.dtype[name].kind == "f":
                        t[name][i] = rng.choice([np.nan, np.inf, -np.inf, 1e308, -1e308, 0.0, -1.0, 1e-320])
                    else:
                        info = np.iinfo(t.dtype[name])
                        t[name][i] = rng.choice([info.max, info.min, 0, 1, 21, 255])
                    d[...] = t
        except ImportError:
            h5.write_bytes(mutate_binary(h5.read_bytes(), rng))
    inputs = {p for p in folder.rglob("*") if p.is_file()}
    since = time.time()
    time.sleep(0.01)
    rc, err = run([str(bins / "mpm"), "-f", str(folder) + "/", "-i", "mpm.json", "--threads", "1"], folder, timeout)
    return classify(rc, err, folder, since, inputs, last_line_only=False)


TARGETS = {"tcl": case_tcl, "fem2mpm": case_fem2mpm, "mpm": case_mpm, "hdf5": case_hdf5}


# ------------------------------------------------------------------------------------------ driver

def one_case(target, index, seed, bins, work, keep, timeout, seeds):
    rng = random.Random(f"{seed}:{target}:{index}")
    folder = Path(tempfile.mkdtemp(prefix=f"{target}_{index}_", dir=work))
    try:
        outcome = TARGETS[target](rng, folder, bins, seeds, timeout)
    except Exception as e:  # a harness failure is reported, never hidden
        outcome = "crash"
        (folder / "harness_error.txt").write_text(repr(e))
    if outcome in BAD and keep is not None:
        dst = keep / f"{target}_{index}_{outcome.replace(' ', '_')}"
        shutil.rmtree(dst, ignore_errors=True)
        shutil.copytree(folder, dst, symlinks=True)
    shutil.rmtree(folder, ignore_errors=True)
    return target, index, outcome


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", required=True, help="folder holding fem_tcl, fem2mpm and mpm")
    ap.add_argument("--cases", type=int, default=75, help="cases per target")
    ap.add_argument("--targets", default=",".join(TARGETS), help="comma-separated subset of " + ",".join(TARGETS))
    ap.add_argument("--seed", default="1")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--timeout", type=float, default=30.0, help="seconds per case before it counts as a hang")
    ap.add_argument("--max-seconds", type=float, default=None,
                    help="stop starting new cases after this long and report the cases run (the table says how many)")
    ap.add_argument("--work", default=None, help="scratch folder (default: a fresh temporary folder, removed)")
    ap.add_argument("--keep", default=None, help="where failing inputs are kept (default: <work>/failures)")
    args = ap.parse_args()

    bins = Path(args.bin).resolve()
    for p in ("fem_tcl", "fem2mpm", "mpm"):
        if not (bins / p).exists():
            sys.exit(f"fuzz.py: {bins / p} not found (build first)")
    own_work = args.work is None
    work = Path(args.work or tempfile.mkdtemp(prefix="geoflow_fuzz_"))
    work.mkdir(parents=True, exist_ok=True)
    keep = Path(args.keep) if args.keep else work / "failures"
    keep.mkdir(parents=True, exist_ok=True)
    seeds = {"tcl": tcl_seeds()}
    targets = [t for t in args.targets.split(",") if t]
    counts = {t: {o: 0 for o in OUTCOMES} for t in targets}
    start = time.time()
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = [pool.submit(one_case, t, i, args.seed, bins, work, keep, args.timeout, seeds)
                   for i in range(args.cases) for t in targets]
        for f in concurrent.futures.as_completed(futures):
            if f.cancelled():
                continue
            t, i, outcome = f.result()
            counts[t][outcome] += 1
            if args.max_seconds is not None and time.time() - start > args.max_seconds:
                for g in futures:
                    g.cancel()
    elapsed = time.time() - start

    width = max(len(o) for o in OUTCOMES)
    print(f"fuzz: up to {args.cases} cases per target, seed {args.seed}, {elapsed:.0f} s, binaries {bins}")
    print(f"{'target':<10}{'cases':>8}" + "".join(f"{o:>{width + 2}}" for o in OUTCOMES))
    for t in targets:
        print(f"{t:<10}{sum(counts[t].values()):>8}" + "".join(f"{counts[t][o]:>{width + 2}}" for o in OUTCOMES))
    bad = sum(counts[t][o] for t in targets for o in BAD)
    if bad:
        print(f"fuzz: {bad} bad outcome(s); inputs kept in {keep}")
    elif own_work:
        shutil.rmtree(work, ignore_errors=True)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
