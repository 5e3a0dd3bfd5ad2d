"""`scheme = "auto"` against RK4 on every bundled example that names no scheme (docs/implicit.md,
"scheme = auto"): each example runs as it stands with `scheme = "auto"` and with
`scheme = "rk4"`, and the largest difference of any channel's minimum, maximum or mean in
summary.json, relative to that channel's largest magnitude, is printed with the scheme auto
chose. Wall times are indicative only (use `hawser bench` for CPU time).

With `--reference`, each example also runs with RK4 at `safety_factor = 0.2` (a quarter of the
default step) as the converged reference, and both `auto` and RK4 at its default step are
compared with it (an example with a fixed `time_step` has no other RK4 step: its reference is
its own run). The samples are the example's own output times in every run, so the comparison
is of the solutions at the same instants; a peak between samples is missed alike by all three.

Usage: python3 scripts/auto_vs_rk4.py [--reference] [HAWSER_BINARY [example,example,...]]
"""
import json, os, re, subprocess, sys, time, shutil, tempfile
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
args = [a for a in sys.argv[1:] if a != "--reference"]
REFERENCE = "--reference" in sys.argv[1:]
BIN = os.path.abspath(args[0]) if args else f"{ROOT}/target/release/hawser"
OUT = tempfile.mkdtemp(prefix="hawser_auto_vs_rk4_")
shutil.copytree(f"{ROOT}/examples/data", f"{OUT}/data", dirs_exist_ok=True)
names = args[1].split(",") if len(args) > 1 else None
# The runs: name, the lines added to [simulation].
RUNS = [("auto", 'scheme = "auto"'), ("rk4", 'scheme = "rk4"')]
if REFERENCE:
    RUNS.append(("reference", 'scheme = "rk4"\nsafety_factor = 0.2'))


def worst(a, r_):
    """The largest difference of a channel's min, max or mean between summaries `a` and the
    reference `r_`, relative to the reference channel's largest magnitude. Channels whose
    largest magnitude is below 1e-8 (a quantity that is zero but for round-off, such as the
    roll of a towed body in a symmetric tow, ~1e-11 rad) are left out."""
    w = (0, "")
    for ch in r_:
        if ch not in a: continue
        rng = max(abs(r_[ch]["max"]), abs(r_[ch]["min"]))
        if rng < 1e-8: continue
        for k in ["min", "max", "mean"]:
            if r_[ch][k] is None or a[ch][k] is None: continue
            d = abs(a[ch][k] - r_[ch][k]) / rng
            if d > w[0]: w = (d, f"{ch}.{k} {a[ch][k]:.6g} vs {r_[ch][k]:.6g}")
    return w


for f in sorted(os.listdir(f"{ROOT}/examples")):
    if not f.endswith(".toml"): continue
    n = f[:-5]
    if names and n not in names: continue
    text = open(f"{ROOT}/examples/{f}").read()
    if re.search(r"^scheme\s*=", text, re.M): continue
    res = {}
    for tag, lines in RUNS:
        t = re.sub(r"^\[simulation\]\n", f"[simulation]\n{lines}\n", text, count=1, flags=re.M)
        p = f"{OUT}/{n}_{tag}.toml"; open(p, "w").write(t)
        od = f"{OUT}/out_{n}_{tag}"
        shutil.rmtree(od, ignore_errors=True)
        w0 = time.time()
        r = subprocess.run([BIN, "run", p, "--out", od], capture_output=True, text=True, cwd=OUT)
        wall = time.time() - w0
        choice = [l for l in r.stderr.splitlines() if l.startswith("scheme:")]
        if r.returncode != 0:
            print(n, tag, "FAILED", r.stderr[-800:]); res[tag] = None; continue
        s = json.load(open(f"{od}/summary.json"))
        res[tag] = (s["channels"], wall, choice[0][:90] if choice else "")
    if not res.get("auto") or not res.get("rk4"): continue
    if REFERENCE:
        if not res.get("reference"): continue
        ref = res["reference"][0]
        wa, wr = worst(res["auto"][0], ref), worst(res["rk4"][0], ref)
        print(f"{n}: against RK4 at safety 0.2 ({res['reference'][1]:.0f} s wall): auto worst "
              f"{wa[0]*100:.3f} % ({wa[1]}), rk4 worst {wr[0]*100:.3f} % ({wr[1]}); "
              f"{res['auto'][2]}", flush=True)
    else:
        w = worst(res["auto"][0], res["rk4"][0])
        print(f"{n}: auto {res['auto'][1]:.1f} s wall, rk4 {res['rk4'][1]:.1f} s wall; worst "
              f"{w[0]*100:.3f} % of range ({w[1]}); {res['auto'][2]}", flush=True)
