"""Security items of the reliability issue: DOCTYPEs refused before any parser or checker, the LLM client's
redirects and cache key, caches that cannot run code on load. Real parsers, a real HTTP server on loopback, real
pickles."""

from __future__ import annotations

import json
import pickle
import threading
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path

import pytest

from txt2sce_ros import signed_cache
from txt2sce_ros.errors import InputError, SimulationFault
from txt2sce_ros.text.llm import ChatClient, LlmConfig
from txt2sce_ros.xmlsafe import refuse_doctype

from .cases import LAUGHS, XXE_DOCTYPE
from .workspace import esmini

SEED = esmini("xosc", "cut-in_simple.xosc")


@pytest.mark.parametrize("prolog", [XXE_DOCTYPE, LAUGHS, "<!-- a comment -->\n<!DOCTYPE OpenSCENARIO>\n",
                                    '<?xml version="1.0"?><?pi x?>\n<!doctype OpenSCENARIO SYSTEM "x.dtd">'])
def test_every_reader_refuses_a_doctype(tmp_path: Path, prolog: str) -> None:
    from scenario_player import load_scenario
    from txt2sce_ros.road import load_network
    from txt2sce_ros.xosc.validate import qc_check, validate_xosc

    body = SEED.read_text(encoding="utf-8").split("?>", 1)[1]
    bad = tmp_path / "bad.xosc"
    bad.write_text(prolog + body, encoding="utf-8")
    for read in (lambda: load_scenario(bad), lambda: validate_xosc(bad.read_bytes(), source=str(bad)),
                 lambda: qc_check(bad)):
        with pytest.raises(InputError, match="DOCTYPE"):
            read()
    xodr = tmp_path / "bad.xodr"
    xodr.write_text(prolog + esmini("xodr", "straight_500m.xodr").read_text().split("?>", 1)[1])
    with pytest.raises(InputError, match="DOCTYPE"):
        load_network(xodr)


def test_doctype_check_reads_only_the_prolog() -> None:
    refuse_doctype(b'<?xml version="1.0"?>\n<a><![CDATA[<!DOCTYPE x>]]></a>')     # inside the document: fine
    refuse_doctype(SEED.read_bytes())
    with pytest.raises(InputError, match="line 3"):
        refuse_doctype(b'<?xml version="1.0"?>\n<!-- c -->\n<!DOCTYPE a [<!ENTITY e "x">]><a/>', "f.xosc")
    with pytest.raises(InputError):
        refuse_doctype('<!DOCTYPE a><a/>'.encode("utf-16"))


class _Redirector(BaseHTTPRequestHandler):
    def log_message(self, *args: object) -> None:
        pass

    def do_POST(self) -> None:  # noqa: N802
        self.server.seen.append((self.path, self.headers.get("Authorization")))  # type: ignore[attr-defined]
        if self.path.startswith("/v1/"):
            self.send_response(302)
            self.send_header("Location", f"http://127.0.0.1:{self.server.server_address[1]}/other/chat/completions")
            self.end_headers()
            return
        data = json.dumps({"choices": [{"message": {"content": "answer from " + self.path}}]}).encode()
        self.send_response(200)
        self.send_header("Content-Length", str(len(data)))
        self.end_headers()
        self.wfile.write(data)


@pytest.fixture()
def redirector():
    srv = ThreadingHTTPServer(("127.0.0.1", 0), _Redirector)
    srv.seen = []  # type: ignore[attr-defined]
    th = threading.Thread(target=srv.serve_forever, daemon=True)
    th.start()
    yield srv
    srv.shutdown()
    srv.server_close()


def test_llm_client_follows_no_redirect_with_the_key(redirector, tmp_path: Path, monkeypatch) -> None:
    monkeypatch.setenv("TXT2SCE_LLM_API_KEY", "sk-secret")
    port = redirector.server_address[1]
    client = ChatClient(LlmConfig(base_url=f"http://127.0.0.1:{port}/v1", model="m", cache=tmp_path, retries=0))
    with pytest.raises(SimulationFault, match="redirect"):
        client.complete([{"role": "user", "content": "hi"}])
    assert redirector.seen == [("/v1/chat/completions", "Bearer sk-secret")]     # the 302 target never asked


def test_llm_cache_is_keyed_by_server(redirector, tmp_path: Path, monkeypatch) -> None:
    monkeypatch.delenv("TXT2SCE_LLM_API_KEY", raising=False)
    port = redirector.server_address[1]
    msgs = [{"role": "user", "content": "same prompt"}]
    a = ChatClient(LlmConfig(base_url=f"http://127.0.0.1:{port}/a", model="m", cache=tmp_path))
    b = ChatClient(LlmConfig(base_url=f"http://127.0.0.1:{port}/b", model="m", cache=tmp_path))
    assert a.complete(msgs) == "answer from /a/chat/completions"
    assert b.complete(msgs) == "answer from /b/chat/completions"    # not server a's cached answer
    assert a.complete(msgs) == "answer from /a/chat/completions" and a.cache_hits == 1


@pytest.mark.parametrize("url,timeout", [("file:///etc/passwd", 10.0), ("http://", 10.0),
                                         ("https://x.example", float("nan")), ("https://x.example", -1.0)])
def test_llm_settings_are_validated(url: str, timeout: float) -> None:
    with pytest.raises(InputError):
        LlmConfig(base_url=url, timeout_s=timeout)


class _Payload:
    """Unpickling this runs `Path(marker).touch()`: what a planted cache entry would do."""

    def __init__(self, marker: Path) -> None:
        self.marker = marker

    def __reduce__(self):
        return (Path.touch, (self.marker,))


def test_a_planted_cache_entry_is_never_unpickled(tmp_path: Path, monkeypatch) -> None:
    monkeypatch.setenv("TXT2SCE_CACHE_KEY", str(tmp_path / "key" / "cache.key"))
    signed_cache._key.cache_clear()
    entry = tmp_path / "cache" / "entry.pickle"
    signed_cache.store(entry, {"good": 1})
    assert signed_cache.load(entry) == {"good": 1}
    marker = tmp_path / "pwned"
    payload = pickle.dumps(_Payload(marker))
    entry.write_bytes(payload)                                   # an unsigned pickle
    assert signed_cache.load(entry) is None and not marker.exists()
    entry.write_bytes(b"\0" * signed_cache.TAG_BYTES + payload)  # a forged tag
    assert signed_cache.load(entry) is None and not marker.exists()
    good = tmp_path / "cache" / "other.pickle"
    signed_cache.store(good, {"x": 2})
    entry.write_bytes(good.read_bytes()[:signed_cache.TAG_BYTES] + payload)   # a real tag of other bytes
    assert signed_cache.load(entry) is None and not marker.exists()


def test_a_key_others_can_read_disables_the_cache(tmp_path: Path, monkeypatch) -> None:
    key = tmp_path / "cache.key"
    key.write_bytes(b"k" * 32)
    key.chmod(0o644)
    monkeypatch.setenv("TXT2SCE_CACHE_KEY", str(key))
    signed_cache._key.cache_clear()
    signed_cache.store(tmp_path / "e.pickle", 1)
    assert not (tmp_path / "e.pickle").exists() and signed_cache.load(tmp_path / "e.pickle") is None
    signed_cache._key.cache_clear()


def test_map_database_cache_rebuilds_a_tampered_entry(tmp_path: Path, monkeypatch) -> None:
    from txt2sce_ros.mapdb.cache import cache_path, load_map_database

    monkeypatch.setenv("TXT2SCE_CACHE", str(tmp_path / "cache"))
    monkeypatch.setenv("TXT2SCE_CACHE_KEY", str(tmp_path / "key"))
    signed_cache._key.cache_clear()
    xodr = esmini("xodr", "straight_500m.xodr")
    first = load_map_database(xodr)
    assert load_map_database(xodr).from_cache
    marker = tmp_path / "pwned"
    cache_path(first.sha256).write_bytes(pickle.dumps(_Payload(marker)))
    again = load_map_database(xodr)
    assert not again.from_cache and not marker.exists() and again.sha256 == first.sha256
    signed_cache._key.cache_clear()
