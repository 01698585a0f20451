"""The LLM backend against a real chat-completions HTTP server on 127.0.0.1 that plays recorded answers.

The recorded answers are a dev report's gold sketch cut into the dialogue's five steps, so a faithful client must
rebuild exactly that sketch. The server can fail on purpose (5xx, slow answers, non-JSON text) to test retries,
timeouts and re-asks; the cache test checks a rerun makes no request at all.
"""

from __future__ import annotations

import json
import threading
import time
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path

import pytest

from txt2sce_ros.errors import SimulationFault
from txt2sce_ros.paths import shared_dir
from txt2sce_ros.sketch import ErrorRecord, Sketch, load_sketches
from txt2sce_ros.text.llm import ChatClient, LlmConfig, LlmExtractor
from txt2sce_ros.text.pipeline import sketch_report
from txt2sce_ros.text.readers import ReportInput

REPORTS = shared_dir() / "data" / "reports"
RID = "dmvca-cruise-20191107-r89"  # a scooterist running a red light into a yielding Cruise AV
KEY = "sk-test-loopback-0123456789"


def _gold() -> Sketch:
    return next(s for s in load_sketches(REPORTS / "dev_gold.jsonl") if isinstance(s, Sketch) and s.report_id == RID)


def _text() -> str:
    for line in (REPORTS / "dev.jsonl").read_text(encoding="utf-8").splitlines():
        row = json.loads(line)
        if row["id"] == RID:
            return row["text"]
    raise AssertionError(RID)


def recorded_answers(g: Sketch) -> dict[str, str]:
    d = g.to_dict()
    return {
        "STEP 1": json.dumps({"parties": [{"id": n["id"], "category": n["category"], "mention": "x"}
                                          for n in d["npcs"]]}),
        "STEP 2": json.dumps({"positions": [{"id": n["id"], "position": n["position"], "lane": n["lane"]}
                                            for n in d["npcs"]]}),
        "STEP 3": "```json\n" + json.dumps({"ego": d["ego"], "parties": [
            {"id": n["id"], "start": n["start"], "actions": n["actions"]} for n in d["npcs"]]}) + "\n```",
        "STEP 4": json.dumps({"obstacles": d["obstacles"], "collision": d["collision"]}),
        "STEP 5": json.dumps({"road": d["road"], "environment": d["environment"], "signal_state": d["signal_state"],
                              "missing": d["missing"]}),
    }


class ChatServer(ThreadingHTTPServer):
    daemon_threads = True

    def __init__(self, answers: dict[str, str]) -> None:
        super().__init__(("127.0.0.1", 0), _Handler)
        self.answers = answers
        self.log: list[dict] = []
        self.fail_status: list[int] = []  # statuses to answer with, one per request, before answering normally
        self.delays: list[float] = []  # seconds to wait before answering, one per request
        self.garbage_once: set[str] = set()  # steps whose first answer is not JSON

    @property
    def url(self) -> str:
        return f"http://127.0.0.1:{self.server_address[1]}"


class _Handler(BaseHTTPRequestHandler):
    server: ChatServer

    def log_message(self, *args: object) -> None:  # keep pytest output clean
        pass

    def do_POST(self) -> None:  # noqa: N802 (http.server's naming)
        body = json.loads(self.rfile.read(int(self.headers["Content-Length"])))
        self.server.log.append({"path": self.path, "auth": self.headers.get("Authorization"), "body": body})
        if self.server.delays:
            time.sleep(self.server.delays.pop(0))
        if self.server.fail_status:
            status = self.server.fail_status.pop(0)
            self.send_response(status)
            self.end_headers()
            self.wfile.write(b'{"error": "recorded failure"}')
            return
        users = [m["content"] for m in body["messages"] if m["role"] == "user"]
        step = next(s for s in ("WEAK SLOTS", "STEP 5", "STEP 4", "STEP 3", "STEP 2", "STEP 1")
                    if any(s in u for u in users))
        content = self.server.answers[step]
        if step in self.server.garbage_once and "not valid" not in users[-1]:
            self.server.garbage_once.discard(step)
            content = "Sure! The AV did a left turn, then stopped."
        payload = {"id": "cmpl-1", "object": "chat.completion", "model": body["model"],
                   "choices": [{"index": 0, "message": {"role": "assistant", "content": content},
                                "finish_reason": "stop"}]}
        data = json.dumps(payload).encode()
        try:
            self.send_response(200)
            self.send_header("Content-Type", "application/json")
            self.send_header("Content-Length", str(len(data)))
            self.end_headers()
            self.wfile.write(data)
        except (BrokenPipeError, ConnectionResetError):
            pass  # the client timed out and hung up


@pytest.fixture()
def server():
    srv = ChatServer(recorded_answers(_gold()))
    th = threading.Thread(target=srv.serve_forever, daemon=True)
    th.start()
    yield srv
    srv.shutdown()
    srv.server_close()


def _extractor(srv: ChatServer, cache: Path, **kw: object) -> LlmExtractor:
    cfg = LlmConfig(base_url=srv.url, model="recorded-model", cache=cache, backoff_s=0.01, **kw)  # type: ignore
    return LlmExtractor(ChatClient(cfg))


def test_dialogue_protocol_and_merge(server: ChatServer, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("TXT2SCE_LLM_API_KEY", KEY)
    ex = _extractor(server, tmp_path / "cache")
    sk = ex.extract(_text(), RID)
    assert sk == _gold()
    assert len(server.log) == 5 and ex.client.requests_made == 5
    for k, req in enumerate(server.log):
        assert req["path"] == "/chat/completions"
        assert req["auth"] == f"Bearer {KEY}"
        body = req["body"]
        assert body["model"] == "recorded-model" and body["temperature"] == 0.0 and body["stream"] is False
        # One growing conversation: system + k (user, assistant) pairs + the new question.
        assert [m["role"] for m in body["messages"]] == ["system"] + ["user", "assistant"] * k + ["user"]
        assert f"STEP {k + 1} of 5" in body["messages"][-1]["content"]
    assert "scooterist" in server.log[0]["body"]["messages"][1]["content"]  # the narrative goes in step 1
    cached = list((tmp_path / "cache").rglob("*.answer"))
    assert len(cached) == 5
    assert all(KEY.encode() not in p.read_bytes() for p in cached)


def test_cache_hit_makes_no_request(server: ChatServer, tmp_path: Path) -> None:
    first = _extractor(server, tmp_path / "cache").extract(_text(), RID)
    assert len(server.log) == 5
    again = _extractor(server, tmp_path / "cache")
    second = again.extract(_text(), RID)
    assert second == first and len(server.log) == 5
    assert again.client.requests_made == 0 and again.client.cache_hits == 5
    other_model = LlmExtractor(ChatClient(LlmConfig(base_url=server.url, model="another-model",
                                                    cache=tmp_path / "cache")))
    other_model.extract(_text(), RID)
    assert len(server.log) == 10  # the cache key includes the model



def test_a_cache_entry_that_does_not_verify_is_asked_again(server: ChatServer, tmp_path: Path) -> None:
    """An answer written into the cache by anyone without the key (or damaged) never reaches a sketch."""
    import pickle

    first = _extractor(server, tmp_path / "cache").extract(_text(), RID)
    entries = sorted((tmp_path / "cache").rglob("*.answer"))
    forged = pickle.dumps({"model": "recorded-model", "content": '{"npcs": []}'})
    entries[0].write_bytes(b"\0" * 32 + forged)   # a well-formed entry with a tag made without the key
    again = _extractor(server, tmp_path / "cache")
    assert again.extract(_text(), RID) == first
    assert again.client.requests_made == 1 and again.client.cache_hits == 4

def test_retries_on_5xx_then_succeeds(server: ChatServer, tmp_path: Path) -> None:
    server.fail_status = [503, 500]
    ex = _extractor(server, tmp_path / "c", retries=3)
    assert ex.extract(_text(), RID) == _gold()
    assert ex.client.requests_made == 7  # two failures, then the five steps


def test_timeout_is_retried(server: ChatServer, tmp_path: Path) -> None:
    server.delays = [1.5]
    ex = _extractor(server, tmp_path / "c", timeout_s=0.4, retries=2)
    assert ex.extract(_text(), RID) == _gold()
    assert ex.client.requests_made == 6


def test_gives_up_after_bounded_retries(server: ChatServer, tmp_path: Path) -> None:
    server.fail_status = [502] * 10
    ex = _extractor(server, tmp_path / "c", retries=2)
    with pytest.raises(SimulationFault, match="after 3 attempts"):
        ex.extract(_text(), RID)
    assert len(server.log) == 3
    # In a batch the failure is one error record, not a crash.
    server.fail_status = [502] * 10
    rec = sketch_report(ReportInput(RID, _text(), "mem"), backend="llm", llm=_extractor(server, tmp_path / "d",
                                                                                          retries=1))
    assert isinstance(rec, ErrorRecord) and "attempts" in rec.error


def test_refused_request_is_not_retried(server: ChatServer, tmp_path: Path) -> None:
    server.fail_status = [401]
    ex = _extractor(server, tmp_path / "c", retries=3)
    with pytest.raises(SimulationFault, match="HTTP 401"):
        ex.extract(_text(), RID)
    assert len(server.log) == 1


def test_invalid_json_is_reasked(server: ChatServer, tmp_path: Path) -> None:
    server.garbage_once = {"STEP 3"}
    ex = _extractor(server, tmp_path / "c")
    assert ex.extract(_text(), RID) == _gold()
    assert ex.reasks == 1 and len(server.log) == 6
    reask = server.log[3]["body"]["messages"]
    assert reask[-1]["role"] == "user" and "not valid" in reask[-1]["content"]


def test_schema_invalid_answer_is_reasked_then_fails(server: ChatServer, tmp_path: Path) -> None:
    server.answers["STEP 2"] = json.dumps({"positions": [{"id": "npc1", "position": "R9", "lane": None}]})
    ex = _extractor(server, tmp_path / "c", max_reasks=2)
    rec = sketch_report(ReportInput(RID, _text(), "mem"), backend="llm", llm=ex)
    assert isinstance(rec, ErrorRecord) and "2_positions" in rec.error and "R9" in rec.error
    assert ex.reasks == 2 and len(server.log) == 1 + 3  # step 1, then step 2 asked three times


def test_hybrid_asks_only_for_incomplete_reports(server: ChatServer, tmp_path: Path) -> None:
    ex = _extractor(server, tmp_path / "c")
    out = sketch_report(ReportInput(RID, _text(), "mem"), backend="hybrid", llm=ex)
    assert isinstance(out, Sketch) and out.is_buildable and server.log == []
    # A narrative the rules cannot complete (no party, no place) goes to the LLM, whose complete answer is kept.
    vague = ReportInput(RID, "The AV was damaged. No injuries were reported.", "mem")
    out = sketch_report(vague, backend="hybrid", llm=ex)
    assert isinstance(out, Sketch) and out == _gold() and len(server.log) == 5


def test_hybrid_asks_only_for_weak_slots_and_keeps_valid_answers(server: ChatServer, tmp_path: Path) -> None:
    from txt2sce_ros.text.extractor import extract_weighed

    # Two lanes said of one car: its place is read, but the evidence conflicts.
    text = "The AV was traveling northbound on Main Street when a car in the left lane, then in the right lane, " \
           "struck the AV."
    rules, weak = extract_weighed(text, "weak-1")
    assert rules.is_buildable and "npcs[0].position" in weak
    server.answers["WEAK SLOTS"] = json.dumps({"npcs[0].position": "R6", "npcs[0].lane": "left",
                                               "npcs[0].actions": "af", "npcs[0].category": "bus"})
    ex = _extractor(server, tmp_path / "c")
    out = sketch_report(ReportInput("weak-1", text, "mem"), backend="hybrid", llm=ex)
    assert isinstance(out, Sketch) and len(server.log) == 1
    asked = server.log[0]["body"]["messages"][-1]["content"]
    assert "npcs[0].position" in asked and "Hard cases" in server.log[0]["body"]["messages"][0]["content"]
    assert (out.npcs[0].position, out.npcs[0].lane) == ("R6", "left")
    assert out.npcs[0].category == rules.npcs[0].category  # a slot not asked for is never taken
    if "npcs[0].actions" in weak:
        assert out.npcs[0].actions == "af"
    # An answer that would break the sketch (a lane for a junction position) is dropped slot by slot.
    server.answers["WEAK SLOTS"] = json.dumps({"npcs[0].position": "R9", "npcs[0].lane": "left"})
    out2 = sketch_report(ReportInput("weak-1", text + " ", "mem"), backend="hybrid", llm=_extractor(
        server, tmp_path / "d"))
    assert isinstance(out2, Sketch) and out2.npcs[0].position == rules.npcs[0].position


def test_cli_llm_backend_flags_and_env(server: ChatServer, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from txt2sce_ros.cli.main import main

    monkeypatch.setenv("TXT2SCE_CACHE", str(tmp_path / "cache"))
    monkeypatch.setenv("DEEPSEEK_API_KEY", KEY)
    monkeypatch.delenv("TXT2SCE_LLM_API_KEY", raising=False)
    src = tmp_path / "one.jsonl"
    src.write_text(json.dumps({"id": RID, "text": _text()}) + "\n", encoding="utf-8")
    out = tmp_path / "out.jsonl"
    assert main(["extract", str(src), "--out", str(out), "--backend", "llm", "--base-url", server.url,
                 "--model", "recorded-model", "--quiet"]) == 0
    (line,) = out.read_text(encoding="utf-8").splitlines()
    assert Sketch.from_dict(json.loads(line)) == _gold()
    assert {r["auth"] for r in server.log} == {f"Bearer {KEY}"} and len(server.log) == 5
    assert KEY not in out.read_text(encoding="utf-8")
    assert all(KEY.encode() not in p.read_bytes() for p in (tmp_path / "cache").rglob("*.answer"))


def test_hybrid_keeps_the_rules_sketch_when_the_server_fails_and_a_dead_server_costs_one_attempt_a_report(
        server: ChatServer, tmp_path: Path) -> None:
    from txt2sce_ros.text.extractor import extract_weighed
    from txt2sce_ros.text.llm import DOWN_AFTER

    text = "The AV was traveling northbound on Main Street when a car in the left lane, then in the right lane, " \
           "struck the AV."
    server.fail_status = [503] * 100
    ex = _extractor(server, tmp_path / "c", retries=3)
    outs = [sketch_report(ReportInput(f"weak-{k}", text + " " * k, "mem"), backend="hybrid", llm=ex)
            for k in range(6)]
    rules = extract_weighed(text, "weak-0")[0]
    # Nothing lost: every report keeps the rules' reading, and the extractor says which were not double-checked.
    assert all(isinstance(o, Sketch) and o.npcs == rules.npcs for o in outs)
    assert [rid for rid, _ in ex.not_consulted] == [f"weak-{k}" for k in range(6)]
    assert "HTTP 503" in ex.not_consulted[-1][1]
    # Retries for the first requests only; once the server is known down, one attempt per report.
    assert len(server.log) == DOWN_AFTER * 4 + (6 - DOWN_AFTER)
    # One answer brings the retries back.
    server.fail_status = []
    server.answers["WEAK SLOTS"] = "{}"
    out = sketch_report(ReportInput("weak-9", text + " " * 9, "mem"), backend="hybrid", llm=ex)
    assert isinstance(out, Sketch) and ex.client.down_streak == 0


def test_cli_without_a_key_for_the_default_server_stops_at_once(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                                 capsys: pytest.CaptureFixture[str]) -> None:
    from txt2sce_ros.cli.main import main

    for name in ("TXT2SCE_LLM_API_KEY", "DEEPSEEK_API_KEY", "TXT2SCE_LLM_BASE_URL"):
        monkeypatch.delenv(name, raising=False)
    src = tmp_path / "one.jsonl"
    src.write_text(json.dumps({"id": RID, "text": _text()}) + "\n", encoding="utf-8")
    assert main(["extract", str(src), "--out", str(tmp_path / "o.jsonl"), "--backend", "hybrid", "--quiet"]) == 2
    assert not (tmp_path / "o.jsonl").exists()       # stopped before any report, not one refusal per report
    assert "no API key for https://api.deepseek.com" in capsys.readouterr().err


def test_hybrid_merge_moves_a_party_between_a_junction_leg_and_the_avs_road() -> None:
    from txt2sce_ros.text.llm import merge_slots

    rules = _gold()  # the scooterist came from the AV's right at the junction: R3, no lane
    asked = ("npcs[0].position", "npcs[0].lane", "npcs[0].actions")
    # Onto the AV's road: the position and the lane are only valid together, so they are merged together.
    out = merge_slots(rules, {"npcs[0].position": "R6", "npcs[0].lane": "left", "npcs[0].actions": "af"}, asked)
    assert (out.npcs[0].position, out.npcs[0].lane, out.npcs[0].actions) == ("R6", "left", "af")
    # ... and back to a junction leg, which clears the lane whatever the answer said of it.
    back = merge_slots(out, {"npcs[0].position": "R1", "npcs[0].lane": "left"}, asked)
    assert (back.npcs[0].position, back.npcs[0].lane, back.npcs[0].actions) == ("R1", None, "af")
    # An invalid field is dropped on its own: the valid answers of the same party still count.
    part = merge_slots(rules, {"npcs[0].position": "R9", "npcs[0].actions": "ad"}, asked)
    assert (part.npcs[0].position, part.npcs[0].actions) == ("R3", "ad")
    # A slot not asked for is never taken.
    assert merge_slots(rules, {"npcs[0].actions": "ad"}, ("npcs[0].position",)) == rules
