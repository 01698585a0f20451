"""Optional LLM backend: any OpenAI-compatible chat-completions server (DeepSeek by default, or a local
Ollama / vLLM / llama.cpp server), in the paper's multi-turn dialogue.

The dialogue asks, in one conversation: parties and categories -> positions -> action sequences -> obstacles and
contact -> road and conditions (prompts in `txt2sce_ros/text/prompts/`). Each answer is parsed as JSON and checked
against its fragment of the sketch schema; an invalid answer is re-asked with the problem named (bounded), and the
five answers are merged into one sketch, validated as a whole.

Answers are cached on disk keyed by server, model and a hash of the whole prompt (all messages), so a rerun asks
nothing and gives the same bytes; entries are HMAC-signed (`signed_cache`), and one that does not verify is asked
again. The API key comes only from the environment (`TXT2SCE_LLM_API_KEY`, else `DEEPSEEK_API_KEY`); it is sent in
the Authorization header and never logged, cached or written.
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import re
import socket
import time
import urllib.error
import urllib.parse
import urllib.request
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import InputError, SimulationFault
from .. import signed_cache
from ..paths import cache_dir
from ..sketch import LANED_POSITIONS, Sketch, load_schema, validate_sketch_dict

PROMPTS_DIR = Path(__file__).resolve().parent / "prompts"
STEPS = ("1_parties", "2_positions", "3_actions", "4_obstacles", "5_conditions")
KEY_ENV = ("TXT2SCE_LLM_API_KEY", "DEEPSEEK_API_KEY")
DEFAULT_BASE_URL = "https://api.deepseek.com"
DEFAULT_MODEL = "deepseek-chat"


@dataclass(frozen=True)
class LlmConfig:
    base_url: str = DEFAULT_BASE_URL
    model: str = DEFAULT_MODEL
    timeout_s: float = 60.0
    retries: int = 3  # extra attempts after a 5xx, a 429 or a timeout
    backoff_s: float = 1.0  # doubled per retry
    max_reasks: int = 2  # re-asks of one step after an invalid answer
    temperature: float = 0.0
    max_tokens: int = 800
    cache: Path | None = None  # None: <cache_dir>/llm

    def __post_init__(self) -> None:
        where = "LLM settings"
        url = urllib.parse.urlsplit(str(self.base_url))
        if url.scheme not in ("http", "https") or not url.hostname:
            raise InputError(f"base URL must be http:// or https:// with a host, got {self.base_url!r}",
                             source=where, element="base_url")
        for name, low, high in (("timeout_s", 0.0, 3600.0), ("backoff_s", -1e-12, 600.0),
                                ("temperature", -1e-12, 2.0)):
            value = getattr(self, name)
            if not (isinstance(value, (int, float)) and math.isfinite(value) and low < value <= high):
                raise InputError(f"{name} must be a finite number in ({max(low, 0):g}, {high:g}], got {value!r}",
                                 source=where, element=name)
        for name, high in (("retries", 10), ("max_reasks", 10), ("max_tokens", 100_000)):
            value = getattr(self, name)
            if not (isinstance(value, int) and 0 <= value <= high):
                raise InputError(f"{name} must be an integer in [0, {high}], got {value!r}", source=where,
                                 element=name)

    @classmethod
    def from_settings(cls, settings: dict[str, Any] | None = None, **overrides: Any) -> LlmConfig:
        """Config file values (`config/extract.yaml`, section `llm`), then env (`TXT2SCE_LLM_BASE_URL`,
        `TXT2SCE_LLM_MODEL`), then explicit overrides (CLI flags) that are not None."""
        s = dict(settings or {})
        if os.environ.get("TXT2SCE_LLM_BASE_URL"):
            s["base_url"] = os.environ["TXT2SCE_LLM_BASE_URL"]
        if os.environ.get("TXT2SCE_LLM_MODEL"):
            s["model"] = os.environ["TXT2SCE_LLM_MODEL"]
        s.update({k: v for k, v in overrides.items() if v is not None})
        known = {f for f in cls.__dataclass_fields__}
        unknown = set(s) - known
        if unknown:
            raise InputError(f"unknown LLM settings: {', '.join(sorted(unknown))}", source="config/extract.yaml",
                             element="llm")
        if s.get("cache") is not None:
            s["cache"] = Path(s["cache"])
        return cls(**s)


#: Largest answer read from the server (a chat answer is a few kB; the bound keeps memory flat).
MAX_ANSWER_BYTES = 4 * 1024 * 1024


class _NoRedirect(urllib.request.HTTPRedirectHandler):
    """Refuse every redirect: urllib would re-send the Authorization header to wherever a 30x points."""

    def redirect_request(self, req, fp, code, msg, headers, newurl):  # type: ignore[no-untyped-def]
        return None


_OPENER = urllib.request.build_opener(_NoRedirect)
DOWN_AFTER = 2


def api_key() -> str | None:
    for name in KEY_ENV:
        if os.environ.get(name):
            return os.environ[name]
    return None


@dataclass
class ChatClient:
    """Chat completions over HTTP (urllib, no extra dependency) with retries and an on-disk answer cache."""

    config: LlmConfig
    requests_made: int = 0
    cache_hits: int = 0
    _sleep: Any = field(default=time.sleep, repr=False)
    #: Requests in a row that got no answer after all their attempts. From `DOWN_AFTER` on, each request makes
    #: one attempt only: a batch against a server that is down costs one attempt per report, not retries and
    #: backoff for every one. An answer resets it.
    down_streak: int = 0

    def _cache_path(self, messages: list[dict[str, str]]) -> Path:
        root = self.config.cache or (cache_dir() / "llm")
        # Keyed by server too: the same model name on another server is another model (and another trust).
        key = hashlib.sha256(json.dumps({"server": self.config.base_url.rstrip("/"), "model": self.config.model,
                                         "messages": messages, "temperature": self.config.temperature},
                                        sort_keys=True, ensure_ascii=False).encode()).hexdigest()
        safe_model = re.sub(r"[^\w.-]+", "_", self.config.model)
        return root / safe_model / key[:2] / f"{key}.answer"

    def complete(self, messages: list[dict[str, str]]) -> str:
        """The assistant's answer to `messages` (from the cache when this exact prompt was asked before)."""
        path = self._cache_path(messages)
        # Signed like the map caches (signed_cache): an answer someone else put in the cache directory would
        # become a sketch unchecked; one that does not verify (or is damaged) is asked again.
        entry = signed_cache.load(path)
        if isinstance(entry, dict) and isinstance(entry.get("content"), str):
            self.cache_hits += 1
            return entry["content"]
        content = self._post(messages)
        signed_cache.store(path, {"model": self.config.model, "content": content})
        return content

    def _post(self, messages: list[dict[str, str]]) -> str:
        url = self.config.base_url.rstrip("/") + "/chat/completions"
        body = json.dumps({"model": self.config.model, "messages": messages, "temperature": self.config.temperature,
                           "max_tokens": self.config.max_tokens, "stream": False}).encode()
        headers = {"Content-Type": "application/json", "Accept": "application/json"}
        key = api_key()
        if key:
            headers["Authorization"] = f"Bearer {key}"
        last = ""
        attempts = 1 if self.down_streak >= DOWN_AFTER else self.config.retries + 1
        for attempt in range(attempts):
            if attempt:
                self._sleep(self.config.backoff_s * 2 ** (attempt - 1))
            self.requests_made += 1
            req = urllib.request.Request(url, data=body, headers=headers, method="POST")
            try:
                with _OPENER.open(req, timeout=self.config.timeout_s) as resp:
                    raw = resp.read(MAX_ANSWER_BYTES + 1)
                if len(raw) > MAX_ANSWER_BYTES:
                    raise SimulationFault(f"LLM server answer longer than {MAX_ANSWER_BYTES} bytes", source=url)
                payload = json.loads(raw.decode("utf-8"))
                content = str(payload["choices"][0]["message"]["content"])
                self.down_streak = 0
                return content
            except urllib.error.HTTPError as exc:
                last = f"HTTP {exc.code}"
                if 300 <= exc.code < 400:
                    raise SimulationFault(f"LLM server redirected ({last} to {exc.headers.get('Location', '?')}); "
                                          "redirects are not followed, so the API key never goes to another "
                                          "address: set --base-url to the final address", source=url) from exc
                if exc.code in (429,) or exc.code >= 500:
                    continue
                raise SimulationFault(f"LLM server refused the request ({last}; check model name and API key)",
                                      source=url) from exc
            except (TimeoutError, socket.timeout) as exc:
                last = "timeout"
                del exc
                continue
            except urllib.error.URLError as exc:
                if isinstance(exc.reason, (TimeoutError, socket.timeout)):
                    last = "timeout"
                    continue
                last = f"connection failed ({exc.reason})"
                continue
            except (json.JSONDecodeError, UnicodeDecodeError, KeyError, IndexError, TypeError) as exc:
                raise SimulationFault(f"LLM server answered outside the chat-completions protocol ({exc!r})",
                                      source=url) from exc
        self.down_streak += 1
        down = f"; {self.down_streak} requests in a row unanswered, so one attempt each" \
            if self.down_streak > DOWN_AFTER else ""
        raise SimulationFault(f"LLM server failed after {attempts} attempt{'s' * (attempts > 1)} (last: {last}{down})",
                              source=url)


def load_prompt(name: str) -> str:
    return (PROMPTS_DIR / f"{name}.md").read_text(encoding="utf-8")


def _fragment_schemas() -> dict[str, dict[str, Any]]:
    """Per-step JSON Schemas, cut from the sketch schema so both always agree."""
    sk = load_schema()["properties"]
    npc = sk["npcs"]["items"]["properties"]
    party_id = npc["id"]

    def obj(props: dict[str, Any], required: list[str]) -> dict[str, Any]:
        return {"type": "object", "properties": props, "required": required}

    return {
        "1_parties": obj({"parties": {"type": "array", "items": obj(
            {"id": party_id, "category": npc["category"]}, ["id", "category"])}}, ["parties"]),
        "2_positions": obj({"positions": {"type": "array", "items": obj(
            {"id": party_id, "position": npc["position"], "lane": npc["lane"]}, ["id", "position", "lane"])}},
            ["positions"]),
        "3_actions": obj({"ego": sk["ego"], "parties": {"type": "array", "items": obj(
            {"id": party_id, "start": npc["start"], "actions": npc["actions"]}, ["id", "start", "actions"])}},
            ["ego", "parties"]),
        "4_obstacles": obj({"obstacles": sk["obstacles"], "collision": sk["collision"]}, ["obstacles", "collision"]),
        "5_conditions": obj({"road": sk["road"], "environment": sk["environment"],
                             "signal_state": sk["signal_state"], "missing": sk["missing"]},
                            ["road", "environment", "signal_state", "missing"]),
    }


def parse_answer(text: str) -> Any:
    """The JSON object in an answer, tolerating a code fence or prose around it; InputError if there is none."""
    t = text.strip()
    fence = re.search(r"```(?:json)?\s*(.*?)```", t, re.S)
    if fence:
        t = fence.group(1).strip()
    try:
        return json.loads(t)
    except json.JSONDecodeError:
        start, end = t.find("{"), t.rfind("}")
        if 0 <= start < end:
            try:
                return json.loads(t[start:end + 1])
            except json.JSONDecodeError:
                pass
    raise InputError("answer is not a JSON object", element="answer")


@dataclass
class LlmExtractor:
    """The multi-turn dialogue over a ChatClient."""

    client: ChatClient
    reasks: int = 0  # total re-asks made (for reports and tests)
    #: Hybrid reports whose server request failed: (report id, why). Their rules' sketch was kept.
    not_consulted: list[tuple[str, str]] = field(default_factory=list)

    @classmethod
    def from_config(cls, config: LlmConfig) -> LlmExtractor:
        return cls(ChatClient(config))

    def _ask(self, messages: list[dict[str, str]], step: str, check: Any) -> Any:
        from jsonschema import Draft202012Validator

        validator = Draft202012Validator(_fragment_schemas()[step])
        for attempt in range(self.client.config.max_reasks + 1):
            answer = self.client.complete(messages)
            messages.append({"role": "assistant", "content": answer})
            try:
                data = parse_answer(answer)
                errs = sorted(validator.iter_errors(data), key=lambda e: list(map(str, e.absolute_path)))
                if errs:
                    where = "/".join(map(str, errs[0].absolute_path)) or "$"
                    raise InputError(errs[0].message, element=where)
                check(data)
                return data
            except InputError as exc:
                if attempt == self.client.config.max_reasks:
                    raise InputError(f"LLM answer to {step} still invalid after {attempt} re-asks: {exc.message}",
                                     element=exc.element or step) from exc
                self.reasks += 1
                messages.append({"role": "user", "content": (
                    f"That answer is not valid ({exc.element}: {exc.message}). Answer {step.split('_', 1)[0]} "
                    "again with one JSON object exactly in the requested shape, nothing else.")})
        raise AssertionError("unreachable")

    def extract(self, narrative: str, report_id: str) -> Sketch:
        """Run the five-step dialogue on one narrative and merge the answers into a validated sketch."""
        if not narrative.strip():
            raise InputError("empty narrative", source=report_id)
        messages = [{"role": "system", "content": load_prompt("system")}]
        answers: dict[str, Any] = {}
        ids: list[str] = []

        def same_ids(key: str) -> Any:
            def check(data: Any) -> None:
                got = [p["id"] for p in data[key]]
                if sorted(got) != sorted(ids):
                    raise InputError(f"ids {got} do not match the parties of step 1 {ids}", element=key)
            return check

        def numbered(data: Any) -> None:
            got = [p["id"] for p in data["parties"]]
            if got != [f"npc{i}" for i in range(1, len(got) + 1)]:
                raise InputError("ids must be npc1, npc2, ... in order", element="parties")

        checks = {"1_parties": numbered, "2_positions": same_ids("positions"), "3_actions": same_ids("parties"),
                  "4_obstacles": lambda d: None, "5_conditions": lambda d: None}
        for step in STEPS:
            prompt = load_prompt(step)
            if step == "1_parties":
                prompt = prompt.replace("{narrative}", narrative.strip())
            messages.append({"role": "user", "content": prompt})
            answers[step] = self._ask(messages, step, checks[step])
            if step == "1_parties":
                ids = [p["id"] for p in answers[step]["parties"]]
        return merge_answers(report_id, answers)

    def refine(self, offline: Sketch, narrative: str, weak: tuple[str, ...] = ()) -> Sketch:
        """Hybrid mode. A report the rules flag incomplete gets the whole dialogue (its answer is taken only if
        complete); a complete one with weak slots gets one question about those slots only, and each answer that
        keeps the sketch valid replaces the rules' value; otherwise the rules' sketch stands."""
        if not offline.is_buildable:
            try:
                asked = self.extract(narrative, offline.report_id)
            except InputError:
                return offline
            return asked if asked.is_buildable else offline
        if not weak:
            return offline
        return self.ask_slots(offline, narrative, weak)

    def ask_slots(self, offline: Sketch, narrative: str, slots: tuple[str, ...]) -> Sketch:
        """One question for the listed slot paths (`npcs[K].position|lane|actions`); answers merged slot by slot."""
        prompt = (load_prompt("hybrid").replace("{narrative}", narrative.strip())
                  .replace("{sketch}", json.dumps({k: v for k, v in offline.to_dict().items() if k != "evidence"}))
                  .replace("{slots}", ", ".join(slots)))
        messages = [{"role": "system", "content": load_prompt("system")}, {"role": "user", "content": prompt}]
        try:
            answer = parse_answer(self.client.complete(messages))
        except InputError:
            return offline
        if not isinstance(answer, dict):
            return offline
        return merge_slots(offline, answer, slots)


#: The slot paths `hybrid` may ask about: one NPC's position, lane or action string.
SLOT_PATH = re.compile(r"npcs\[(\d+)\]\.(position|lane|actions)")


def merge_slots(offline: Sketch, answer: dict[str, Any], slots: tuple[str, ...]) -> Sketch:
    """The answers for the asked `slots` merged into the rules' sketch, one NPC at a time: its answered fields
    together first (a party moved between a junction position and the AV's road changes its position and its lane
    at once, and neither alone is a valid sketch), else field by field; an answer that would make the sketch
    invalid is dropped, and a position off the AV's road clears the lane."""
    d = offline.to_dict()
    fields: dict[int, dict[str, Any]] = {}
    for slot in slots:
        m = SLOT_PATH.fullmatch(slot)
        if m and slot in answer and int(m.group(1)) < len(d["npcs"]):
            fields.setdefault(int(m.group(1)), {})[m.group(2)] = answer[slot]

    def tried(base: dict[str, Any], k: int, update: dict[str, Any]) -> dict[str, Any] | None:
        trial = json.loads(json.dumps(base))
        npc = trial["npcs"][k]
        npc.update(update)
        if "position" in update and npc["position"] not in LANED_POSITIONS:
            npc["lane"] = None
        return None if validate_sketch_dict(trial) else trial

    for k, update in fields.items():
        whole = tried(d, k, update)
        if whole is not None:
            d = whole
            continue
        for name, value in update.items():
            d = tried(d, k, {name: value}) or d
    return Sketch.from_dict(d) if d != offline.to_dict() else offline


def configured_llm(backend: str, settings: dict[str, Any] | None, *, base_url: str | None = None,
                   model: str | None = None, timeout_s: float | None = None) -> LlmExtractor:
    """The client for `--backend llm|hybrid`: `config/extract.yaml`'s settings with the command line's overrides.
    Refused up front (InputError) when it would talk to the default server with no key: every request would be
    refused, so it is said once instead of once per report."""
    llm = LlmExtractor.from_config(LlmConfig.from_settings(settings, base_url=base_url, model=model,
                                                           timeout_s=timeout_s))
    if api_key() is None and llm.client.config.base_url.rstrip("/") == DEFAULT_BASE_URL:
        raise InputError(f"--backend {backend}: no API key for {DEFAULT_BASE_URL} (set {' or '.join(KEY_ENV)}, "
                         f"or --base-url a server that needs none, e.g. a local Ollama or vLLM)")
    return llm


def merge_answers(report_id: str, answers: dict[str, Any]) -> Sketch:
    """The five step answers -> one sketch dict -> validated Sketch (InputError naming the field otherwise)."""
    pos = {p["id"]: p for p in answers["2_positions"]["positions"]}
    act = {p["id"]: p for p in answers["3_actions"]["parties"]}
    npcs = []
    for p in answers["1_parties"]["parties"]:
        q, a = pos[p["id"]], act[p["id"]]
        npcs.append({"id": p["id"], "category": p["category"], "position": q["position"],
                     "lane": q["lane"] if q["position"] in LANED_POSITIONS else None,
                     "start": a["start"], "actions": a["actions"]})
    cond = answers["5_conditions"]
    d = {"schema": "txt2sce.sketch/1", "report_id": report_id, "road": cond["road"],
         "environment": cond["environment"], "signal_state": cond["signal_state"],
         "ego": answers["3_actions"]["ego"], "npcs": npcs, "obstacles": answers["4_obstacles"]["obstacles"],
         "collision": answers["4_obstacles"]["collision"], "missing": cond["missing"]}
    problems = validate_sketch_dict(d)
    if problems:
        raise InputError(f"merged LLM answers do not form a valid sketch: {problems[0]}", source=report_id)
    return Sketch.from_dict(d)
