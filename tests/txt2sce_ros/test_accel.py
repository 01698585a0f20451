"""The compiled build of the hot modules (`txt2sce_ros/accel.py`): the same runs bit for bit, and never a build of
other bytes than the source beside it."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from txt2sce_ros import accel

ROOT = Path(__file__).resolve().parents[2]

# Digests of whole runs, printed with the modules that loaded compiled: the closed loop with the stand-in planner
# and the oracle (`standin_planner.regress`: every trajectory row, the verdict record) and the storyboard alone
# (`scenario_player.fingerprint`).
_RUNS = textwrap.dedent("""
    import json, sys
    from pathlib import Path
    from scenario_player.fingerprint import run_digest
    from standin_planner.regress import digest_run
    from txt2sce_ros import accel
    out = {}
    for f in sys.argv[1:]:
        out[f"{Path(f).stem}/closed-loop"] = digest_run(Path(f))[0]
        out[f"{Path(f).stem}/storyboard"] = run_digest(f, "storyboard").exact
    print(json.dumps({"runs": out, "compiled": sorted(accel.active())}))
""")


def _run(files: list[str], **env: str) -> dict:
    e = {**os.environ, "PYTHONPATH": str(ROOT), **env}
    done = subprocess.run([sys.executable, "-c", _RUNS, *files], capture_output=True, text=True, env=e,
                          cwd=ROOT, timeout=600)
    assert done.returncode == 0, done.stderr[-2000:]
    return json.loads(done.stdout.strip().splitlines()[-1])


def test_compiled_modules_run_the_same_bits_as_the_source() -> None:
    built = [m for m, s in accel.status().items() if s == "built"]
    if not built:
        pytest.skip("no compiled build here (`txt2sce accel build`; `make setup` makes one)")
    files = sorted(str(p) for p in (ROOT / "examples" / "scenarios").glob("*.xosc"))
    compiled = _run(files)
    plain = _run(files, TXT2SCE_ACCEL="0")
    assert plain["compiled"] == []
    # every module whose build matches its source was loaded compiled (those the runs import)
    assert set(compiled["compiled"]) >= {"standin_planner.planner", "scenario_player.simulation",
                                         "oracle_monitor.oracle"} & set(built)
    assert compiled["compiled"]
    assert compiled["runs"] == plain["runs"] and len(plain["runs"]) == 2 * len(files)


def test_a_build_is_used_only_for_the_bytes_it_was_built_from(tmp_path: Path) -> None:
    pytest.importorskip("Cython")
    pkg = tmp_path / "src" / "accel_probe"
    pkg.mkdir(parents=True)
    (pkg / "__init__.py").write_text("")
    mod = pkg / "calc.py"
    mod.write_text("def f(x):\n    return 0.1 * x + 0.2\n")
    cache = tmp_path / "cache"
    sys.path.insert(0, str(tmp_path / "src"))
    try:
        assert accel.status(["accel_probe.calc"], cache) == {"accel_probe.calc": "not built"}
        try:
            first = accel.build(["accel_probe.calc"], cache, jobs=1)
        except RuntimeError as exc:
            if "built" in accel.status().values():
                raise               # the project's own modules were compiled here: so must this one be
            pytest.skip(f"no working C compiler for Cython here ({exc})")
        assert first == {"accel_probe.calc": "built"}
        assert accel.build(["accel_probe.calc"], cache, jobs=1) == {"accel_probe.calc": "up to date"}
    finally:
        sys.path.remove(str(tmp_path / "src"))
    probe = textwrap.dedent(f"""
        import sys
        from pathlib import Path
        from txt2sce_ros import accel
        sys.meta_path.insert(0, accel.CompiledFinder(["accel_probe.calc"], Path({str(cache)!r})))
        import accel_probe.calc as m
        print(m.__file__, m.f(3.0))
    """)

    def load(**env: str) -> tuple[str, str]:
        e = {**os.environ, "PYTHONPATH": os.pathsep.join([str(tmp_path / "src"), str(ROOT)]), **env}
        done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, env=e, timeout=120)
        assert done.returncode == 0, done.stderr
        where, value = done.stdout.split()
        return where, value

    where, value = load()
    assert where.endswith(accel.artifact("accel_probe.calc", mod.read_bytes(), cache).name)
    assert value == repr(0.1 * 3.0 + 0.2)                 # the same float as the interpreter's
    mod.write_text("def f(x):\n    return 0.1 * x + 0.3\n")     # edited after the build: the source runs
    where, value = load()
    assert where == str(mod) and value == repr(0.1 * 3.0 + 0.3)
    # building each new version keeps only the newest few builds of the module
    sys.path.insert(0, str(tmp_path / "src"))
    try:
        for k in range(accel.KEEP_BUILDS + 1):
            mod.write_text(f"def f(x):\n    return 0.1 * x + {k}\n")
            assert accel.build(["accel_probe.calc"], cache, jobs=1) == {"accel_probe.calc": "built"}
    finally:
        sys.path.remove(str(tmp_path / "src"))
    kept = list((cache / sys.implementation.cache_tag / "accel_probe.calc").iterdir())
    assert len(kept) == accel.KEEP_BUILDS
    assert accel.artifact("accel_probe.calc", mod.read_bytes(), cache).parent in kept


def test_switched_off_loads_nothing_compiled() -> None:
    probe = "import standin_planner.planner as p; from txt2sce_ros import accel; print(p.__file__, len(accel.active()))"
    e = {**os.environ, "PYTHONPATH": str(ROOT), "TXT2SCE_ACCEL": "0"}
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, env=e, timeout=120)
    assert done.returncode == 0, done.stderr
    where, n = done.stdout.split()
    assert where.endswith("standin_planner/planner.py") and n == "0"


def test_build_without_cython_says_so(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "Cython.Build", None)          # `import` of it raises ImportError
    with pytest.raises(RuntimeError, match="not installed"):
        accel.build(["standin_planner.idm"])
