"""`scheme = "auto"` against RK4 on every bundled example that names no scheme (docs/implicit.md,
"scheme = auto"): each example runs as it stands with `scheme = "auto"` and with
`scheme = "rk4"`, and the largest difference of any channel's minimum, maximum or mean in
summary.json, relative to that channel's largest magnitude, is printed with the scheme auto
chose. Wall times are indicative only (use `hawser bench` for CPU time).

Usage: python3 scripts/auto_vs_rk4.py [HAWSER_BINARY [example,example,...]]
"""
import json, os, re, subprocess, sys, time, shutil, tempfile
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BIN = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else f"{ROOT}/target/release/hawser"
OUT = tempfile.mkdtemp(prefix="hawser_auto_vs_rk4_")
shutil.copytree(f"{ROOT}/examples/data", f"{OUT}/data", dirs_exist_ok=True)
names = sys.argv[2].split(",") if len(sys.argv) > 2 else None
rows = []
for f in sorted(os.listdir(f"{ROOT}/examples")):
    if not f.endswith(".toml"): continue
    n = f[:-5]
    if names and n not in names: continue
    text = open(f"{ROOT}/examples/{f}").read()
    if re.search(r"^scheme\s*=", text, re.M): continue
    res = {}
    for scheme in ["auto", "rk4"]:
        t = re.sub(r"^\[simulation\]\n", '[simulation]\nscheme = "auto"\n', text, count=1, flags=re.M) if scheme == "auto" else re.sub(r"^\[simulation\]\n", '[simulation]\nscheme = "rk4"\n', text, count=1, flags=re.M)
        p = f"{OUT}/{n}_{scheme}.toml"; open(p, "w").write(t)
        od = f"{OUT}/out_{n}_{scheme}"
        shutil.rmtree(od, ignore_errors=True)
        w0 = time.time()
        r = subprocess.run([BIN, "run", p, "--out", od], capture_output=True, text=True, cwd=OUT)
        wall = time.time() - w0
        choice = [l for l in r.stderr.splitlines() if l.startswith("scheme:")]
        if r.returncode != 0:
            print(n, scheme, "FAILED", r.stderr[-800:]); res[scheme] = None; continue
        s = json.load(open(f"{od}/summary.json"))
        res[scheme] = (s, wall, choice[0][:90] if choice else "")
    if not res.get("auto") or not res.get("rk4"): continue
    a, r_ = res["auto"][0]["channels"], res["rk4"][0]["channels"]
    worst = (0, "")
    for ch in r_:
        if ch not in a: continue
        rng = max(abs(r_[ch]["max"]), abs(r_[ch]["min"]), 1e-30)
        for k in ["min", "max", "mean"]:
            if r_[ch][k] is None or a[ch][k] is None: continue
            d = abs(a[ch][k] - r_[ch][k]) / rng
            if d > worst[0]: worst = (d, f"{ch}.{k} {a[ch][k]:.6g} vs {r_[ch][k]:.6g}")
    print(f"{n}: auto {res['auto'][1]:.1f} s wall, rk4 {res['rk4'][1]:.1f} s wall; worst {worst[0]*100:.3f} % of range ({worst[1]}); {res['auto'][2]}", flush=True)
