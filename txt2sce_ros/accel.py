"""An optional compiled build of the closed loop's hot modules: the same Python source, compiled by Cython.

The player, the stand-in planner and the oracle run a few hundred Python steps per scenario, thousands of
scenarios per campaign. Compiled as they are (no type declarations, no source changes, C's IEEE doubles with no
contraction of multiply-adds), they run the same operations in the same order: the same bits, about a fifth less
CPU (`docs/performance.md`, session 15; `python -m standin_planner.regress check` proves the bits).

How it is kept safe:
- A compiled module is used only while it was built from the very bytes of the `.py` beside it: the build is stored
  under a hash of the source (and of this interpreter's version) in a cache directory, never next to the source, and
  the import hook (`enable`, called by each package's `__init__`) hashes the source at import. Edit a module and
  the plain source runs until the next `txt2sce accel build`; nothing stale is ever loaded.
- Nothing needs it: without a build (no Cython or compiler, a ROS install, `TXT2SCE_ACCEL=0`) everything imports
  the plain source as before.

`txt2sce accel build` compiles (needs Cython and a C compiler: `make setup` does it); `txt2sce accel status` tells
which modules would load compiled. The cache lives in `$TXT2SCE_ACCEL_DIR`, else `$XDG_CACHE_HOME/txt2sce/accel`
(default `~/.cache/txt2sce/accel`).
"""

from __future__ import annotations

import importlib.machinery
import os
import sys
from pathlib import Path
from typing import Any, Callable, Sequence

#: The modules compiled: where a run spends its CPU (the per-step code of player, planner and oracle), what a
#: recorded run adds (message building, serialisation, MCAP writing; and reading it back to judge), and the
#: extractor's per-sentence reading.
MODULES: tuple[str, ...] = (
    "txt2sce_ros.closed_loop", "txt2sce_ros.ros_io",
    "scenario_player.simulation",
    "scenario_player.world.collision", "scenario_player.world.entity", "scenario_player.world.kinematics",
    "scenario_player.world.lanes", "scenario_player.world.measure", "scenario_player.world.motion",
    "scenario_player.world.pose", "scenario_player.world.signals", "scenario_player.world.world",
    "scenario_player.storyboard.build", "scenario_player.storyboard.element", "scenario_player.storyboard.tree",
    "scenario_player.conditions.base", "scenario_player.conditions.by_entity", "scenario_player.conditions.by_value",
    "standin_planner.planner", "standin_planner.behaviour", "standin_planner.refline", "standin_planner.route",
    "standin_planner.pure_pursuit", "standin_planner.idm", "standin_planner.perception",
    "oracle_monitor.oracle", "oracle_monitor.safety", "oracle_monitor.smartness", "oracle_monitor.smoothness",
    "oracle_monitor.unavoidable", "oracle_monitor.geometry", "oracle_monitor.egopath", "oracle_monitor.signals",
    "oracle_monitor.runwriter", "oracle_monitor.recorder", "oracle_monitor.cdr", "oracle_monitor.steprecords",
    "oracle_monitor.messages", "oracle_monitor.bagread", "oracle_monitor.judge",
    "txt2sce_ros.text.fastre", "txt2sce_ros.text.mentions", "txt2sce_ros.text.extractor", "txt2sce_ros.text.actions",
    "txt2sce_ros.text.story", "txt2sce_ros.text.spans", "txt2sce_ros.text.relations", "txt2sce_ros.text.scene",
    "txt2sce_ros.text.sequences", "txt2sce_ros.text.positions", "txt2sce_ros.text.lexicon",
)

#: Cython's settings. Annotations are not types to it here (the source's hints are for readers and mypy, and a
#: `list` hint with a tuple default must stay legal); `binding` keeps functions introspectable as in Python.
DIRECTIVES: dict[str, Any] = {"language_level": 3, "binding": True, "annotation_typing": False}
#: No fused multiply-add (it would round differently from Python's separate multiply and add); no fast-math.
CFLAGS: tuple[str, ...] = ("-O2", "-ffp-contract=off", "-fno-fast-math")
#: Part of every build's key: change it when DIRECTIVES or CFLAGS change, so older builds are no longer used.
BUILD_TAG = "accel-1"

ENV_SWITCH = "TXT2SCE_ACCEL"            # "0" / "off": always the plain source
ENV_DIR = "TXT2SCE_ACCEL_DIR"
#: Where the compiler's output is kept when a build leaves something out or fails.
_KEPT_LOG = Path(os.environ.get("TMPDIR") or "/tmp") / "txt2sce_accel_build.log"


def cache_dir() -> Path:
    if os.environ.get(ENV_DIR):
        return Path(os.environ[ENV_DIR])
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "txt2sce" / "accel"


def switched_off() -> bool:
    return os.environ.get(ENV_SWITCH, "").strip().lower() in ("0", "off", "no", "false")


def build_key(source: bytes) -> str:
    """The key of a build of `source` on this interpreter (its exact version: builds are not shared between two)."""
    import hashlib          # here, not at the top: every cold start imports this module

    h = hashlib.sha256()
    for part in (BUILD_TAG.encode(), sys.version.encode(), source):
        h.update(len(part).to_bytes(8, "little"))
        h.update(part)
    return h.hexdigest()[:24]


def artifact(name: str, source: bytes, root: Path | None = None) -> Path:
    """Where the build of module `name` from `source` is (or would be) kept."""
    leaf = name.rpartition(".")[2]
    suffix = importlib.machinery.EXTENSION_SUFFIXES[0]
    return (root or cache_dir()) / sys.implementation.cache_tag / name / build_key(source) / f"{leaf}{suffix}"


def _source_of(name: str, path: Sequence[str] | None) -> Path | None:
    """The `.py` file the normal import would load for `name` (None: not a plain source module)."""
    spec = importlib.machinery.PathFinder.find_spec(name, path)
    if spec is None or not spec.origin or not spec.origin.endswith(".py"):
        return None
    return Path(spec.origin)


class CompiledFinder:
    """Loads a module of `modules` from its build when the build's key matches the source's bytes now (a
    `sys.meta_path` finder, ahead of the normal ones; any other module it leaves to them)."""

    def __init__(self, modules: Sequence[str], root: Path) -> None:
        self.modules = frozenset(modules)
        self.root = root
        self.loaded: dict[str, str] = {}             # module -> file it was loaded from (compiled ones only)

    def find_spec(self, fullname: str, path: Sequence[str] | None, target: Any = None) -> Any:
        if fullname not in self.modules:
            return None
        src = _source_of(fullname, path)
        if src is None:
            return None
        try:
            so = artifact(fullname, src.read_bytes(), self.root)
        except OSError:
            return None
        if not so.is_file():
            return None                                 # not built from these bytes: the plain source loads
        loader = importlib.machinery.ExtensionFileLoader(fullname, str(so))
        self.loaded[fullname] = str(so)
        spec = importlib.machinery.ModuleSpec(fullname, loader, origin=str(so))
        spec.has_location = True                        # so the module's __file__ names the build
        return spec


_finder: CompiledFinder | None = None


def enable(modules: Sequence[str] = MODULES, root: Path | None = None) -> None:
    """Install the import hook (once; a no-op under `TXT2SCE_ACCEL=0`). Called by the packages' `__init__`, before
    any of their modules is imported."""
    global _finder
    if _finder is not None or switched_off():
        return
    _finder = CompiledFinder(modules, root or cache_dir())
    sys.meta_path.insert(0, _finder)


def active() -> dict[str, str]:
    """The modules loaded compiled so far in this process, and from which file."""
    return dict(_finder.loaded) if _finder is not None else {}


def describe() -> str:
    """One line for benchmarks and logs: how much of the hot code runs compiled in this process's set-up."""
    if switched_off():
        return f"compiled build switched off ({ENV_SWITCH}=0): plain source"
    state = status()
    ready = sum(1 for s in state.values() if s == "built")
    how = "" if ready == len(state) else " (the rest from the plain source: `txt2sce accel build`)"
    return f"compiled build: {ready}/{len(state)} hot modules{how}"


def _package_dirs(modules: Sequence[str]) -> dict[str, Path]:
    """The top-level packages of `modules` and their directories (found as `import` finds them, including an
    editable install's finder, without running them)."""
    import importlib.util

    out = {}
    for top in sorted({m.split(".")[0] for m in modules}):
        spec = importlib.util.find_spec(top)
        if spec is None or not spec.submodule_search_locations:
            raise RuntimeError(f"package {top} cannot be found by import here")
        out[top] = Path(list(spec.submodule_search_locations)[0])
    return out


def sources(modules: Sequence[str] = MODULES) -> dict[str, Path]:
    """Each module's `.py` file."""
    dirs = _package_dirs(modules)
    out = {}
    for name in modules:
        top, _, rest = name.partition(".")
        out[name] = dirs[top].joinpath(*rest.split(".")).with_suffix(".py")
    return out


def status(modules: Sequence[str] = MODULES, root: Path | None = None) -> dict[str, str]:
    """Per module: 'built' (its build matches the source now) or 'not built'."""
    return {name: ("built" if artifact(name, src.read_bytes(), root).is_file() else "not built")
            for name, src in sources(modules).items()}


def build(modules: Sequence[str] = MODULES, root: Path | None = None, *, jobs: int = 2,
          log: Path | None = None, note: Callable[[str], None] = lambda _: None) -> dict[str, str]:
    """Compile every module of `modules` whose source has no build yet; returns module -> 'built' / 'up to date' /
    'not compilable ...' (a construct Cython does not take: that module runs from source; the others are built).

    Raises RuntimeError (one line, the log's path in it) when Cython or the compiler is missing or fails: nothing is
    half-installed then (a build is moved into the cache only once it is complete)."""
    import shutil
    import tempfile

    try:
        from Cython.Build import cythonize
        from setuptools import Distribution, Extension
    except ImportError as exc:
        raise RuntimeError(f"cannot build: {exc.name or exc} is not installed (pip install cython setuptools)") \
            from exc
    root = root or cache_dir()
    # Each source is read once: its build is keyed by the very bytes compiled, so a file edited during the build is
    # not mislabelled.
    data = {name: src.read_bytes() for name, src in sources(modules).items()}
    dests = {name: artifact(name, body, root) for name, body in data.items()}
    result = {name: "up to date" for name, dest in dests.items() if dest.is_file()}
    for name in result:
        del data[name]
    if not data:
        return result
    work = Path(tempfile.mkdtemp(prefix="txt2sce_accel_"))
    log = log or work / "build.log"
    try:
        csrc = work / "src"
        exts = []
        for name, body in data.items():
            copy = csrc.joinpath(*name.split(".")).with_suffix(".py")
            copy.parent.mkdir(parents=True, exist_ok=True)
            copy.write_bytes(body)
            for d in copy.relative_to(csrc).parents:       # package markers, so Cython sees the packages
                if d != Path("."):
                    (csrc / d / "__init__.py").touch()
            exts.append(Extension(name, [str(copy)], extra_compile_args=list(CFLAGS)))
        note(f"compiling {len(exts)} modules with Cython ({jobs} jobs); log: {log}")
        with _output_to(log):
            # A module Cython cannot compile (a construct it does not support) is left out and runs from source.
            exts = cythonize(exts, compiler_directives=DIRECTIVES, quiet=True, force=True, nthreads=jobs,
                             exclude_failures=True)
        left_out = sorted(set(data) - {e.name for e in exts})
        for name in left_out:
            result[name] = f"not compilable (runs from source; Cython's reasons: {_KEPT_LOG})"
            del data[name]
        if left_out:
            shutil.copyfile(log, _KEPT_LOG)
            note(f"Cython could not compile {', '.join(left_out)}: they run from source ({_KEPT_LOG})")
        if not exts:
            return result
        with _output_to(log):
            dist = Distribution({"ext_modules": exts, "script_name": "txt2sce-accel",
                                 "script_args": ["build_ext", "--build-lib", str(work / "lib"),
                                                 "--build-temp", str(work / "tmp"), "-j", str(jobs)]})
            dist.parse_command_line()
            dist.run_commands()
        for name in data:
            dest = dests[name]
            built = (work / "lib").joinpath(*name.split(".")[:-1]) / dest.name
            dest.parent.mkdir(parents=True, exist_ok=True)
            part = dest.with_name(dest.name + ".part")
            shutil.copyfile(built, part)
            os.replace(part, dest)
            result[name] = "built"
            _prune(dest.parent.parent)
    except (Exception, SystemExit) as exc:      # distutils reports a failed compile as SystemExit
        if log.exists() and log != _KEPT_LOG:
            shutil.copyfile(log, _KEPT_LOG)
        raise RuntimeError(f"the compiled build failed ({type(exc).__name__}: {exc}); the plain source is used; "
                           f"compiler output: {_KEPT_LOG}") from None
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return result


#: Builds kept per module (one per version of its source; ~1 MB each): enough for a few checkouts side by side.
KEEP_BUILDS = 4


def _prune(module_dir: Path) -> None:
    """Remove all but the `KEEP_BUILDS` newest builds of one module (older versions of its source)."""
    import shutil

    builds = sorted((d for d in module_dir.iterdir() if d.is_dir()), key=lambda d: d.stat().st_mtime, reverse=True)
    for old in builds[KEEP_BUILDS:]:
        shutil.rmtree(old, ignore_errors=True)


class _output_to:
    """Send this process's stdout and stderr (file descriptors too: the compiler is a child process) to a file."""

    def __init__(self, path: Path) -> None:
        self.path = path

    def __enter__(self) -> None:
        sys.stdout.flush()
        sys.stderr.flush()
        self.file = open(self.path, "ab")
        self.saved = os.dup(1), os.dup(2)
        os.dup2(self.file.fileno(), 1)
        os.dup2(self.file.fileno(), 2)

    def __exit__(self, *exc: object) -> None:
        sys.stdout.flush()
        sys.stderr.flush()
        os.dup2(self.saved[0], 1)
        os.dup2(self.saved[1], 2)
        os.close(self.saved[0])
        os.close(self.saved[1])
        self.file.close()
