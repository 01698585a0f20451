"""Headless Chromium (Debian's `chromium`) for page tests: render a local HTML file to a PNG screenshot.

Flags keep it offline and stateless: no sandbox (containers), no GPU, no background networking, component updates,
sync or first-run work, and a fresh profile directory per call.
"""

from __future__ import annotations

import shutil
import subprocess
import tempfile
from pathlib import Path

FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--no-first-run", "--hide-scrollbars")


def chromium() -> str | None:
    return shutil.which("chromium") or shutil.which("chromium-browser")


def screenshot(page: Path, png: Path, *, width: int = 1400, height: int = 1800, timeout: float = 120.0) -> Path:
    """Render `page` at width × height CSS pixels into `png`; raises if the browser writes no image."""
    exe = chromium()
    if exe is None:
        raise FileNotFoundError("chromium is not installed (apt-get install chromium)")
    with tempfile.TemporaryDirectory(prefix="txt2sce_chromium_") as profile:
        subprocess.run([exe, *FLAGS, f"--user-data-dir={profile}", f"--window-size={width},{height}",
                        f"--screenshot={png}", page.resolve().as_uri()],
                       check=True, capture_output=True, timeout=timeout)
    if not png.is_file() or png.stat().st_size == 0:
        raise RuntimeError(f"chromium wrote no screenshot of {page}")
    return png


def dump_dom(page: Path, *, timeout: float = 120.0) -> str:
    """The DOM after the page loaded, serialised by the browser."""
    exe = chromium()
    if exe is None:
        raise FileNotFoundError("chromium is not installed (apt-get install chromium)")
    with tempfile.TemporaryDirectory(prefix="txt2sce_chromium_") as profile:
        done = subprocess.run([exe, *FLAGS, f"--user-data-dir={profile}", "--dump-dom", page.resolve().as_uri()],
                              check=True, capture_output=True, text=True, timeout=timeout)
    return done.stdout
