"""One simulation session: a downloaded program on its own CPU, run by its own thread.

The thread owns the CPU. Everything that changes it (commands from the WebSocket, REST calls) is
queued and carried out by the thread between scans, or at a hold in the middle of one, so a scan
never sees a half-made change and no lock is held while the program runs. What clients see is a
``Snapshot`` the thread publishes after a scan (at most ~30 per second, or at once after a
command), and from it each client's frame with only what that client has not seen (``emit``, which
the worker forwards to the server), plus per-client trend samples taken at the end of every scan.
Nothing the thread does waits for a client.

The session belongs to a project (``project_id``), not to a browser tab: clients come and go
(a reload, a second tab) and find it all as they left it. The breakpoints stay set with the
location a client gave (``session_state`` lists them for the next client), and the trend of a
client that left goes on recording (``kept_trend``) so that the next client asking for the same
entries gets its history. ``last_activity`` is when the session was made, its program replaced
or its last client left; REST reads (info, the session list) do not count, so listing the
sessions never keeps an abandoned one alive, and a reload never finds its session reaped.

Time (``set_time``): ``virtual`` runs one scan per cycle of the wall clock and advances the
simulated clock by exactly the cycle time (scans up to 100 ms late are made up, later ones are
lost, as a real CPU's cycle grows); ``real`` also paces scans to the wall clock, and the
simulated clock follows the wall clock (a slow scan makes time jump, as on a real CPU); ``fast``
runs scans back to back; ``pause`` runs none and the clock stands still. A session's scans may
use at most ``cpu_share`` of one core over any 200 ms (fast mode, a heavy program): the limiter
sleeps the rest, so one session cannot starve the others.
"""

from __future__ import annotations

import logging
import threading
import time
from collections import deque
from collections.abc import Callable
from concurrent.futures import Future
from dataclasses import dataclass, field
from typing import Any, TypeVar

from nasaq.cpu import Cpu, Profile
from nasaq.cpu.codegen.compiler import Compiled
from nasaq.diagnostics.phrases import phrase
from nasaq.ir import Area, BlockKind
from nasaq.lang.stl import SourceFile
from nasaq.monitor import targets, watch
from nasaq.monitor.block_info import (
    BlockInfo,
    block_info,
    breakpoint_indices,
    parse_block_name,
)
from nasaq.monitor.debugger import (
    Debugger,
    HoldContext,
    OperatorStopError,
    call_stack,
    hold_state,
    modify_local,
    parse_condition,
)
from nasaq.monitor.download import carry_over, compile_download
from nasaq.monitor.element_status import ElementStatusBuilder
from nasaq.monitor.errors import MonitorError
from nasaq.monitor.frames import FrameState
from nasaq.monitor.graph_elements import GraphElementStatusBuilder, graph_blocks
from nasaq.monitor.graph_sequencer import Controller, graph_layout, status_of_call
from nasaq.monitor.lad_blocks import lad_blocks
from nasaq.monitor.plant_link import PlantLink, no_plant, plant_of
from nasaq.monitor.protocol import (
    BlockStatus,
    CpuState,
    CycleStats,
    ForcedValue,
    GraphOp,
    HoldState,
    Location,
    PlantFrame,
    StepKind,
    TimeModeName,
    TrendSample,
    Value,
    WatchValue,
)
from nasaq.monitor.scheduler import Scheduler
from nasaq.monitor.status import AR2, DI, Recorder
from nasaq.workbench.cpu_properties import CpuProperties, find, properties_of

log = logging.getLogger(__name__)
T = TypeVar("T")
Key = tuple[BlockKind, int]
FRAME_INTERVAL_S = 1 / 30
EARLY_S = 0.001  # on the scheduler a scan may start this much before it is due
SLICE_S = 0.002  # the longest turn of a fast session on the scheduler
CATCH_UP_S = 0.1  # paced scans this late are made up; later ones are lost (the cycle grew)
MAX_WATCH = 500
MAX_TREND = 32
TREND_SAMPLES = 20_000  # kept per client until sent
SHARE_WINDOW_S = 0.2
CODE_KINDS = (BlockKind.OB, BlockKind.FB, BlockKind.FC)


@dataclass(slots=True)
class ClientView:
    """What one connected client subscribed to; its trend samples wait here until sent."""

    cpu: bool = False
    watch: list[str] = field(default_factory=list)
    watch_targets: dict[str, targets.Target | str] = field(default_factory=dict)
    open_block: Key | None = None
    open_networks: frozenset[int] | None = None  # the networks of it on screen; None: all
    trend: list[targets.Target] = field(default_factory=list)
    trend_entries: list[str] = field(default_factory=list)  # as the client wrote them
    samples: deque[TrendSample] = field(default_factory=lambda: deque(maxlen=TREND_SAMPLES))
    history: deque[TrendSample] = field(default_factory=lambda: deque(maxlen=TREND_SAMPLES))
    state: FrameState = field(default_factory=FrameState)


@dataclass(frozen=True, slots=True)
class Snapshot:
    seq: int
    cpu: CpuState
    values: dict[str, WatchValue]
    blocks: dict[Key, BlockStatus]
    hold: HoldState | None
    diagnostics: int  # entries ever made in the diagnostic buffer
    plant: PlantFrame | None = None  # the same object while the plant did not change


class Session:
    def __init__(
        self,
        session_id: str,
        sources: list[SourceFile],
        profile: Profile = Profile.S7_300,
        cycle_ms: float = 10,
        time_mode: TimeModeName = "virtual",
        cpu_share: float = 0.5,
        project_id: int | None = None,
    ) -> None:
        self.id = session_id
        self.project_id = project_id
        self.started_at = time.time()
        self.sources = list(sources)
        self.profile = profile
        self.program = compile_download(self.sources, profile.value)
        self.lad = lad_blocks(self.sources, self.program)
        self.graphs = graph_blocks(self.sources, self.program)
        # The project's cpu.properties (if any) sets the rest; the API resolved profile and cycle.
        self.properties = properties_of(_pairs(self.sources)).properties
        self.cpu = _cpu(self.program, self.properties, profile, cycle_ms)
        found = plant_of(self.sources)  # the project's .plant file (nasaq.monitor.plant_link)
        self.plant = None if found is None else PlantLink(found, self.cpu)
        self.time_mode: TimeModeName = time_mode
        self._resume_mode: TimeModeName = "virtual" if time_mode == "pause" else time_mode
        self.cpu_share = cpu_share
        self.debugger = Debugger(self)
        self.sequencers = Controller()  # S7-Graph's Control Sequencer (graph_sequencer.py)
        self.clients: dict[int, ClientView] = {}
        self.kept_trend: ClientView | None = None  # the trend of a client that left
        self.breakpoint_places: dict[int, dict[str, Any]] = {}  # id: where a client set it
        self.snapshot: Snapshot | None = None
        self.held: HoldContext | None = None
        self.hold_view: HoldState | None = None
        self.last_activity = time.monotonic()
        self.closed = False
        # Where frames go: ``emit(client, frame_json)`` (the worker forwards them to the sockets).
        self.emit: Callable[[int, str], None] | None = None
        self._cond = threading.Condition()
        self._commands: deque[tuple[Callable[[], Any], Future[Any]]] = deque()
        self._infos: dict[Key, BlockInfo] = {}
        self._recorders: dict[Key, Recorder] = {}
        self._debug_keys: frozenset[Key] = frozenset()
        self._block_status: dict[Key, BlockStatus] = {}
        self._seq = 0
        self._urgent = False
        self._stale = False  # a scan ran after the last snapshot
        self._failures = 0
        self._next_publish = 0.0
        self._answer_pending = False  # a command ran: publish right after the next scan
        self._last_capture = 0.0
        self._due = 0.0
        self._scans_left = 0
        self._pause_after_scan = False
        self._resume = False
        self._abort: tuple[str, bool] | None = None
        self._stats: list[float] = []  # last, min, max, sum, count
        self._held_time = 0.0
        self._busy: deque[tuple[float, float]] = deque()  # (end, duration) of recent scans
        self._busy_total = 0.0
        self._real_origin: tuple[float, int] | None = None
        self.scheduler: Scheduler | None = None
        self.owner = "thread"  # who runs the session: "thread" (its own) or "scheduler"
        self._thread = threading.Thread(
            target=self._main, name=f"nasaq-cpu-{session_id}", daemon=True
        )

    @property
    def engine(self) -> Any:
        return self.cpu.engine

    # -- life -----------------------------------------------------------------------------------
    def start(self, scheduler: Scheduler | None = None) -> None:
        """Starts running (the CPU itself stays in STOP until ``run``): on the process's
        ``scheduler`` while nothing can hold the CPU, else on the session's own thread."""
        self.scheduler = scheduler
        if scheduler is None:
            self.owner = "thread"
            self._thread.start()
        else:
            self.owner = "scheduler"
            scheduler.add(self)

    def close(self) -> None:
        with self._cond:
            self.closed = True
            self._cond.notify_all()
        if self.scheduler is not None:
            self.scheduler.remove(self)
        if self._thread.is_alive() and threading.current_thread() is not self._thread:
            self._thread.join(timeout=5)

    def _needs_thread(self) -> bool:
        """A hold blocks the thread that runs the scan, so a session that may hold (breakpoints
        set, a step pending, holding) runs on its own thread, never on the shared scheduler."""
        return self.debugger.active or self.held is not None

    def _to_thread(self) -> None:
        self.owner = "thread"
        if not self._thread.is_alive():
            self._thread.start()
        with self._cond:
            self._cond.notify_all()

    # -- commands -------------------------------------------------------------------------------
    def submit(self, action: Callable[[], T]) -> Future[T]:
        """Runs ``action`` in the CPU thread (between scans or at a hold); its result or
        exception lands in the future."""
        future: Future[T] = Future()
        if self.closed:
            future.set_exception(MonitorError("MON614"))
            return future
        with self._cond:
            self._commands.append((action, future))
            self._cond.notify_all()
        if self.scheduler is not None:
            self.scheduler.wake()
        return future

    def _run_commands(self) -> None:
        ran = False
        while self._commands:
            action, future = self._commands.popleft()
            ran = True
            if not future.set_running_or_notify_cancel():
                continue
            try:
                future.set_result(action())
            except MonitorError as error:
                future.set_exception(error)
            except targets.TargetError as error:
                future.set_exception(MonitorError(error.code, **error.params))
            except OperatorStopError:
                raise
            except Exception as error:  # a bug: the client gets an error, the thread lives on
                future.set_exception(error)
            if self.owner == "scheduler" and self._needs_thread():
                self._to_thread()  # the rest of the commands run there
                break
        if ran:
            self._urgent = True
            self._answer_pending = True

    # The commands below run in the CPU thread (through ``submit``).
    def do_run(self) -> None:
        if self.held is not None:
            self._resume = True
        elif self.cpu.mode != "RUN":
            self._restart(cold=self.properties.startup == "cold")  # the startup property
        elif self.time_mode == "pause":
            self.time_mode = self._resume_mode

    def do_stop(self) -> None:
        if self.held is not None:
            self._abort = ("stop", False)
        self.cpu.stop()
        self._scans_left = 0
        self.debugger.step = None  # a step still waiting (by transition) ends with the run

    def do_restart(self, cold: bool) -> None:
        if self.held is not None:
            self._abort = ("restart", cold)
            return
        self._restart(cold)

    def _restart(self, cold: bool) -> None:
        self._stats = []
        self._real_origin = None
        if self.time_mode == "pause":
            self.time_mode = self._resume_mode
        self._select_variants(capture=False)
        self.cpu.start(cold)
        self._due = 0.0

    def do_set_time(self, mode: TimeModeName, cycle_ms: float | None) -> None:
        if cycle_ms is not None:
            self.cpu.cycle_ms = cycle_ms
        if mode != "pause":
            self._resume_mode = mode
        self.time_mode = mode
        self._real_origin = None
        self._due = 0.0

    def do_set_input(self, text: str, value: Value) -> None:
        target = self._memory_target(text)
        if target.direct is None or not targets.is_input(target):
            raise MonitorError("MON603", target=text, reason=phrase("not_an_input"))
        self.cpu.set_input(target.direct, targets.encode(target, value))

    def do_modify(self, text: str, value: Value) -> None:
        if text.strip().startswith("#"):
            if self.held is None:
                raise MonitorError(
                    "MON607",
                    action=phrase("act_modify", target=text),
                    reason=phrase("locals_only_holding"),
                )
            modify_local(self.held, text, value)
            self._refresh_hold()
            return
        target = self._memory_target(text)
        targets.write(target, self.cpu, value)
        if target.direct is not None and target.direct.area is Area.I:
            # As in PLCSIM, the simulated input module is the source of the inputs: a modified
            # input holds there until changed, instead of being lost at the next PII update.
            self.cpu.set_input(target.direct, targets.encode(target, value))
        if self.held is not None:
            self._refresh_hold()

    def do_force(self, text: str, value: Value) -> None:
        target = self._memory_target(text)
        if target.direct is None or not (targets.is_input(target) or targets.is_output(target)):
            raise MonitorError("MON603", target=text, reason=phrase("force_only_io"))
        self.cpu.force(target.direct, targets.encode(target, value))

    def do_unforce(self, text: str | None) -> None:
        if text is None:
            self.cpu.unforce()
            return
        target = self._memory_target(text)
        if target.direct is None or not (targets.is_input(target) or targets.is_output(target)):
            raise MonitorError("MON603", target=text, reason=phrase("unforce_only_io"))
        self.cpu.unforce(target.direct)

    def do_set_breakpoint(self, location: Location, condition: str | None) -> dict[str, object]:
        """Sets a breakpoint; the same place and condition again (a reloaded page, a second tab
        setting the project's breakpoints) answers the breakpoint already there."""
        where_given = location.model_dump(exclude_none=True)
        for number, place in self.breakpoint_places.items():
            if (
                place["location"] == where_given
                and place["condition"] == (condition or None)
                and number in self.debugger.breakpoints
            ):
                return {key: place[key] for key in ("id", "block", "instructions", "where")}
        info, indices = self._locate(location)
        parsed = parse_condition(condition, self, info) if condition else None
        where = (
            f"{info.name} step {location.step}"
            if location.step is not None
            else f"{info.file or info.name} line {location.line}"
            if location.line is not None
            else f"{info.name} network {location.network}"
            if location.network is not None
            else f"{info.name} instruction {location.instruction}"
        )
        number = self.debugger.add((info.block.kind, info.block.number), indices, parsed, where)
        self.breakpoint_places[number] = {
            "id": number,
            "location": where_given,
            "condition": condition or None,
            "block": info.name,
            "instructions": indices,
            "file": info.file,
            "where": where,
        }
        return {"id": number, "block": info.name, "instructions": indices, "where": where}

    def do_clear_breakpoint(self, number: int | None) -> None:
        self.debugger.remove(number)
        if number is None:
            self.breakpoint_places.clear()
        else:
            self.breakpoint_places.pop(number, None)

    def do_session_state(self) -> dict[str, object]:
        """The breakpoints set (as their clients gave them) and the trend the session records
        (a connected client's, else the one a client left behind): what a client that attaches
        shows again."""
        alive = self.debugger.breakpoints
        places = [place for number, place in self.breakpoint_places.items() if number in alive]
        recorded = [v.trend_entries for v in list(self.clients.values()) if v.trend_entries]
        kept = self.kept_trend
        trend = recorded[-1] if recorded else kept.trend_entries if kept is not None else []
        return {"breakpoints": places, "trend": list(trend)}

    def client_left(self, view: ClientView) -> None:
        """A client detached (called by the worker): the idle time counts from now, and its
        trend goes on recording for the next client (a reload) that asks for it."""
        self.last_activity = time.monotonic()
        if view.trend:
            view.samples.clear()
            self.kept_trend = view

    def do_continue(self) -> None:
        if self.held is not None:
            self._resume = True
            return
        waiting = self.debugger.step is not None  # a step by transition: now run freely
        self.debugger.step = None
        if self.cpu.mode == "RUN" and self.time_mode == "pause":
            self.time_mode = self._resume_mode
            return
        if waiting:
            return
        raise MonitorError(
            "MON607", action=phrase("act_continue"), reason=phrase("cpu_not_holding")
        )

    def do_step(self, by: StepKind, into: bool) -> None:
        if self.cpu.mode != "RUN":
            raise MonitorError("MON607", action=phrase("act_step"), reason=phrase("cpu_in_stop"))
        if by == "transition":
            self._step_by_transition()
            return
        if by == "scan":
            if self.held is not None:
                self._pause_after_scan = True
                self._resume = True
            else:
                self._scans_left = 1
                if self.time_mode != "pause":
                    self._resume_mode = self.time_mode
                    self.time_mode = "pause"
            return
        self.debugger.request_step(by, into, self.held)
        if self.held is not None:
            self._resume = True
        elif self.time_mode == "pause":
            self._scans_left = 1

    def _step_by_transition(self) -> None:
        """Runs (from a hold, a pause or RUN) until a step of a Graph FB is switched on: the
        clock runs again if paused, as the next transition may wait for a step's time."""
        if not any(self.debugger.activations(k) is not None for k in self.program.blocks):
            raise MonitorError("MON629")
        self.debugger.request_step("transition", True, self.held)
        if self.held is not None:
            self._resume = True
        if self.time_mode == "pause":
            self.time_mode = self._resume_mode
            self._scans_left = 0

    def do_run_scans(self, count: int) -> None:
        if self.cpu.mode != "RUN" or self.held is not None:
            raise MonitorError(
                "MON607",
                action=phrase("act_run_scans", count=count),
                reason=phrase("cpu_must_run"),
            )
        if self.time_mode != "pause":
            self._resume_mode = self.time_mode
        self.time_mode = "pause"
        self._scans_left = count

    def do_download(self, sources: list[SourceFile]) -> dict[str, object]:
        """Replaces the program in STOP; memory and the data blocks whose layout is unchanged
        keep their values (new and changed DBs get their initial values)."""
        if self.cpu.mode != "STOP":
            raise MonitorError(
                "MON607", action=phrase("act_download"), reason=phrase("switch_to_stop")
            )
        cycle_ms, properties, profile = self.cpu.cycle_ms, self.properties, self.profile
        if find(_pairs(sources)) is not None:  # a download carries the CPU properties too
            properties = properties_of(_pairs(sources)).properties
            profile, cycle_ms = properties.profile, properties.cycle_ms
        program = compile_download(sources, profile.value)  # for the profile it will run on
        plant = plant_of(sources)  # a bad plant file refuses the download, as a bad program does
        self.profile = profile
        cpu = _cpu(program, properties, self.profile, cycle_ms)
        self.properties = properties
        changed = carry_over(self.program, self.cpu, program, cpu)
        self.sources = list(sources)
        self.program = program
        self.lad = lad_blocks(self.sources, program)
        self.graphs = graph_blocks(self.sources, program)
        self.cpu = cpu
        self.plant = None if plant is None else PlantLink(plant, cpu)  # the process starts again
        self._infos.clear()
        self._recorders.clear()
        self._block_status.clear()
        self._debug_keys = frozenset()
        self.debugger = Debugger(self)
        self.sequencers.clear()
        self.last_activity = time.monotonic()
        self.breakpoint_places.clear()
        self.kept_trend = None
        return {"changed": changed}

    def do_plant_operate(self, control: str, value: int) -> None:
        if self.plant is None:
            raise no_plant()
        self.plant.operate(self.cpu, control, value)

    def do_plant_fault(self, fault: str, on: bool) -> None:
        if self.plant is None:
            raise no_plant()
        self.plant.fault(fault, on)

    def do_plant_reset(self) -> None:
        if self.plant is None:
            raise no_plant()
        self.plant.reset(self.cpu)

    def do_graph_control(self, db: str, op: GraphOp, step: int | None) -> dict[str, object]:
        """A Control Sequencer command to a Graph FB's instance DB, carried out at its next
        call (``nasaq.monitor.graph_sequencer``)."""
        running = self.cpu.mode == "RUN"
        dbs = self.engine.memory.dbs
        return self.sequencers.command(self.program, dbs, running, db, op, step)

    def view(self, client: int) -> ClientView:
        found = self.clients.get(client)
        if found is None:
            raise MonitorError("MON614")
        return found

    def do_watch(self, client: int, entries: list[str]) -> dict[str, object]:
        if len(entries) > MAX_WATCH:
            raise MonitorError(
                "MON605", what=phrase("what_watch"), count=len(entries), limit=MAX_WATCH
            )
        resolved, report = watch.resolve_entries(entries, self.program, self.cpu)
        view = self.view(client)
        view.watch = list(entries)
        view.watch_targets = resolved
        return {"entries": report}

    def do_trend(self, client: int, entries: list[str]) -> dict[str, object]:
        if len(entries) > MAX_TREND:
            raise MonitorError(
                "MON605", what=phrase("what_trend"), count=len(entries), limit=MAX_TREND
            )
        chosen = [self._memory_target(text) for text in entries]
        view = self.view(client)
        donor = self._trend_donor(client, entries)
        view.trend = chosen
        view.trend_entries = list(entries)
        view.samples.clear()
        view.history.clear()
        if donor is not None:  # the same entries are recorded already: start with their history
            view.history.extend(donor.history)
            view.samples.extend(donor.history)
        if self.kept_trend is donor or not entries:
            self.kept_trend = None
        return {"entries": [{"entry": t.text, "type": t.type} for t in chosen]}

    def _trend_donor(self, client: int, entries: list[str]) -> ClientView | None:
        if not entries:
            return None
        kept = self.kept_trend
        if kept is not None and kept.trend_entries == entries:
            return kept
        for number, other in list(self.clients.items()):
            if number != client and other.trend_entries == entries:
                return other
        return None

    def do_open_block(
        self, client: int, name: str | None, networks: list[int] | None = None
    ) -> dict[str, object]:
        view = self.view(client)
        if name is None:
            view.open_block = None
            view.open_networks = None
            return {}
        key = parse_block_name(name, self.program)
        info = self.info(key)
        view.open_block = key
        view.open_networks = None if networks is None else frozenset(networks)
        self._last_capture = 0.0
        return {"block": info.name, "language": info.language, "instructions": len(info.lines)}

    def _networks_on_screen(self, key: Key) -> frozenset[int] | None:
        """The networks of ``key`` some client shows (None: all of them): what is recorded."""
        shown: set[int] = set()
        for view in list(self.clients.values()):
            if view.open_block == key:
                if view.open_networks is None:
                    return None
                shown |= view.open_networks
        return frozenset(shown)

    def _memory_target(self, text: str) -> targets.Target:
        return watch.memory_target(text, self.program, self.cpu)

    def _locate(self, location: Location) -> tuple[BlockInfo, list[int]]:
        if location.step is not None:
            return self._locate_step(location, location.step)
        if location.block is not None:
            info = self.info(parse_block_name(location.block, self.program))
            if location.line is None and location.network is None and location.instruction is None:
                raise MonitorError("MON604", where=info.name, hint=phrase("hint_give_place"))
            return info, breakpoint_indices(info, location)
        if location.file is None or location.line is None:
            raise MonitorError("MON604", where="?", hint=phrase("hint_give_block"))
        wanted = _base_name(location.file)
        line = location.line
        later: list[int] = []
        for key in sorted(self.program.blocks, key=lambda k: (k[0].value, k[1])):
            if key[0] not in CODE_KINDS:
                continue
            info = self.info(key)
            if info.file is None or _base_name(info.file) != wanted:
                continue
            if any(v == line for v in info.lines):
                return info, breakpoint_indices(info, location)
            later += [v for v in info.lines if v is not None and v > line]
        hint = phrase("hint_next_line", line=min(later)) if later else ""
        # next_line: so that a client can offer to move the breakpoint there.
        raise MonitorError(
            "MON604",
            where=phrase("where_line", file=location.file, line=line),
            hint=hint,
            next_line=min(later) if later else None,
        )

    def _locate_step(self, location: Location, step: int) -> tuple[BlockInfo, list[int]]:
        """A step breakpoint: the instructions that switch step ``step`` of the Graph FB that
        ``block`` names, or the one Graph FB compiled from ``file``."""
        if any(v is not None for v in (location.line, location.network, location.instruction)):
            raise MonitorError("MON626")
        if location.block is not None:
            key = parse_block_name(location.block, self.program)
            if self.debugger.activations(key) is None:
                raise MonitorError("MON624", block=self.info(key).name)
        elif location.file is not None:
            wanted = _base_name(location.file)
            keys = [
                k
                for k, block in sorted(self.program.blocks.items(), key=lambda i: i[0][1])
                if k[0] is BlockKind.FB
                and block.file
                and _base_name(block.file) == wanted
                and self.debugger.activations(k) is not None
            ]
            if not keys:
                raise MonitorError("MON627", file=location.file)
            if len(keys) > 1:
                names = ", ".join(self.info(k).name for k in keys)
                raise MonitorError("MON628", file=location.file, blocks=names)
            key = keys[0]
        else:
            raise MonitorError("MON604", where="?", hint=phrase("hint_give_block"))
        found = self.debugger.activations(key)
        assert found is not None
        info = self.info(key)
        indices = found.of_step(step)
        if not indices:
            shown = ", ".join(f"S{n}" for n in list(found.steps)[:24])
            more = ", ..." if len(found.steps) > 24 else ""
            raise MonitorError("MON625", block=info.name, step=step, steps=(shown + more) or "-")
        return info, indices

    # -- block information and instrumentation ---------------------------------------------------
    def info(self, key: Key) -> BlockInfo:
        found = self._infos.get(key)
        if found is None:
            block = self.program.get(*key)
            assert block is not None
            found = self._infos[key] = block_info(block)
            drawn = self.lad.get(key)
            if drawn is not None:  # the language the block is drawn in (the file may say FBD)
                found.language = drawn.language.lower()
        return found

    def _info_of(self, compiled: Compiled) -> BlockInfo:
        return self.info((compiled.block.kind, compiled.block.number))

    def _recorder(self, key: Key) -> Recorder:
        found = self._recorders.get(key)
        if found is None:
            engine = self.engine
            info = self.info(key)
            drawn = self.lad.get(key)
            charted = self.graphs.get(key)
            elements = (
                ElementStatusBuilder(drawn, info)
                if drawn is not None
                else GraphElementStatusBuilder(charted, info)
                if charted is not None
                else None
            )
            found = self._recorders[key] = Recorder(
                info, engine.memory, engine.timers, engine.counters, elements
            )
            layout = graph_layout(info.block)
            if layout is not None:  # an S7-Graph FB: its steps and transitions too
                dbs = engine.memory.dbs
                found.graph = lambda regs: status_of_call(layout, regs[DI], regs[AR2], dbs)
        return found

    def _hooks(self, compiled: Compiled) -> tuple[Callable[..., None], Callable[..., None]]:
        key = (compiled.block.kind, compiled.block.number)
        return self.debugger.before_hook(compiled, self.info(key)), self._recorder(key).hook()

    def _select_variants(self, capture: bool) -> list[Key]:
        """Chooses which blocks run instrumented in the next scan; returns the open blocks
        sampled in it."""
        if not capture and not self._debug_keys and not self.debugger.active:
            return []  # the usual scan: every block runs its fast compilation
        opened = {v.open_block for v in list(self.clients.values()) if v.open_block is not None}
        sampled = sorted(opened, key=lambda k: (k[0].value, k[1])) if capture else []
        if self.debugger.active:
            wanted = frozenset(k for k in self.program.blocks if k[0] in CODE_KINDS)
        else:
            wanted = frozenset(sampled)
        if wanted != self._debug_keys:
            loader = self.engine.loader
            for key in self._debug_keys | wanted:
                if key in wanted:
                    loader.instrumented(key[0], key[1], self._hooks)
                loader.select(key[0], key[1], key in wanted)
            self._debug_keys = wanted
        return sampled

    # -- the hold (runs inside a hook, in the CPU thread) ----------------------------------------
    def hold(self, context: HoldContext) -> None:
        started = time.perf_counter()
        self.held = context
        self._resume = False
        self._refresh_hold()
        try:
            while True:
                with self._cond:
                    while not self._commands and not self.closed:
                        self._cond.wait(1.0)
                self._run_commands()
                if self.closed or self._abort is not None:
                    raise OperatorStopError("SIM527")
                if self._resume:
                    break
                self._refresh_hold()
        finally:
            self._resume = False
            self.held = None
            self.hold_view = None
            self._held_time += time.perf_counter() - started
            self._urgent = True

    def _refresh_hold(self) -> None:
        held = self.held
        if held is None:
            return
        stack = call_stack(held, self.engine.loader.by_filename, self._info_of)
        self.hold_view = hold_state(held, stack)
        key = (held.compiled.block.kind, held.compiled.block.number)
        if any(v.open_block == key for v in list(self.clients.values())):
            # The open block's lines show the values at the hold, as the Locals do.
            recorder = self._recorder(key)
            status = recorder.at_hold(held.frame, held.params, held.regs, self.engine.scans)
            self._block_status[key] = status
        self._publish(force=True)

    # -- the CPU thread --------------------------------------------------------------------------
    def _main(self) -> None:
        while not self.closed:
            if self.owner != "thread":
                with self._cond:
                    if self.owner != "thread" and not self.closed:
                        self._cond.wait(0.5)
                continue
            try:
                self._step_thread()
            except Exception:  # a bug in the monitor: the CPU stops, the session lives on
                self._failed()
            if self.scheduler is not None and not self._needs_thread():
                self.owner = "scheduler"  # nothing can hold any more: back to the scheduler
                self.scheduler.wake()
        self._abort = None

    def _failed(self) -> None:
        self._failures += 1
        if self._failures <= 3:
            log.exception("simulation session %s: internal error", self.id)
        self.cpu.stop()
        self._urgent = True
        time.sleep(0.05)

    def tick(self) -> float | None:
        """The scheduler's turn: carry out the commands, run the scans due within ``EARLY_S``
        (a fast session: for up to ``SLICE_S``); when the session wants the next turn
        (``perf_counter`` time), None when only a command can make it run."""
        try:
            self._run_commands()
            if self.owner != "scheduler" or self.closed:
                return None
            ends = time.perf_counter() + SLICE_S
            while True:
                delay = self._delay()
                if delay is None or delay > EARLY_S:
                    idle = delay is None or delay > FRAME_INTERVAL_S
                    if self._urgent or (self._stale and idle):
                        self._publish(force=True)  # idle now: the clients get the newest state
                    return None if delay is None else time.perf_counter() + delay
                if time.perf_counter() > ends:
                    return time.perf_counter()
                self._scan()
        except Exception:  # a bug in the monitor: the CPU stops, the session lives on
            self._failed()
            return None

    def _step_thread(self) -> None:
        self._run_commands()
        if self.closed:
            return
        delay = self._delay()
        if delay is None or delay > 0:
            if self._urgent or (self._stale and (delay is None or delay > FRAME_INTERVAL_S)):
                self._publish(force=True)  # idle now: the clients get the newest state
            with self._cond:
                if not self._commands and not self.closed:
                    self._cond.wait(0.5 if delay is None else min(delay, 0.5))
            return
        self._scan()

    def _delay(self) -> float | None:
        """Seconds until the next scan may start; None: no scan is due (STOP, pause)."""
        if self.cpu.mode != "RUN":
            return None
        now = time.perf_counter()
        share = self._share_wait(now)
        if self._scans_left > 0:
            return share
        if self.time_mode == "pause":
            return None
        if self.time_mode == "fast":
            return share
        if self._due < now - max(self.cpu.cycle_ms / 1000.0, CATCH_UP_S):
            # The first scan, or far behind (a hold, a long scan): start the rhythm again from
            # now, as a real CPU's cycle simply grows, rather than race through the lost cycles.
            # A few cycles lost to a busy machine are made up, so the pace stays 1:1.
            self._due = now
        return max(self._due - now, share)

    def _share_wait(self, now: float) -> float:
        busy = self._busy
        while busy and busy[0][0] < now - SHARE_WINDOW_S:
            self._busy_total -= busy.popleft()[1]
        used = self._busy_total
        allowed = self.cpu_share * SHARE_WINDOW_S
        return 0.0 if used <= allowed else (used - allowed) / self.cpu_share

    def _scan(self) -> None:
        cpu = self.cpu
        engine = cpu.engine
        now = time.perf_counter()
        capture = now - self._last_capture >= FRAME_INTERVAL_S
        sampled = self._select_variants(capture)
        recorders = [self._recorder(key) for key in sampled]
        for key, recorder in zip(sampled, recorders, strict=True):
            recorder.select(self._networks_on_screen(key))
            recorder.begin()
        if self.time_mode == "real":
            self._follow_wall_clock(now)
        cycle = cpu.cycle_ms / 1000.0
        # Paced scans start at most CATCH_UP_S after they were due; after unpaced ones (fast,
        # run_scans) the rhythm starts again from now.
        late = max(cycle, CATCH_UP_S)
        base = self._due if now - late <= self._due <= now + cycle else now
        self._due = base + cycle
        self._held_time = 0.0
        plant = self.plant
        if plant is not None:
            plant.before_scan(cpu)
        if self.sequencers.boxes:
            self.sequencers.before_scan(engine.memory.dbs)
        started = time.perf_counter()
        cpu.scan()
        elapsed = time.perf_counter() - started - self._held_time
        if plant is not None:
            plant.after_scan(cpu)
        if self._abort is not None:
            action, cold = self._abort
            self._abort = None
            if action == "restart":
                self._restart(cold)
        if recorders:
            self._last_capture = now
            for key, recorder in zip(sampled, recorders, strict=True):
                status = recorder.finish(engine.scans)
                if status is not None:
                    self._block_status[key] = status
        self._count(elapsed)
        if self._scans_left > 0:
            self._scans_left -= 1
        if self._pause_after_scan:
            self._pause_after_scan = False
            if self.time_mode != "pause":
                self._resume_mode = self.time_mode
            self.time_mode = "pause"
        self._sample_trends()
        self._stale = True
        self._publish(force=self._answer_pending)
        self._answer_pending = False
        # The share limiter counts the thread's whole work for the scan, not only the program's.
        finished = time.perf_counter()
        spent = finished - now - self._held_time
        self._busy.append((finished, spent))
        self._busy_total += spent

    def _follow_wall_clock(self, now: float) -> None:
        m = self.engine.m
        if self._real_origin is None:
            self._real_origin = (now, m.now)
        wall_ms = self._real_origin[1] + int((now - self._real_origin[0]) * 1000)
        if wall_ms > m.now:
            m.now = wall_ms

    def _count(self, elapsed: float) -> None:
        ms = elapsed * 1000.0
        stats = self._stats
        if not stats:
            self._stats = [ms, ms, ms, ms, 1.0]
            return
        stats[0] = ms
        stats[1] = min(stats[1], ms)
        stats[2] = max(stats[2], ms)
        stats[3] += ms
        stats[4] += 1.0

    def _sample_trends(self) -> None:
        cpu = self.cpu
        views = list(self.clients.values())
        if self.kept_trend is not None:
            views.append(self.kept_trend)
        for view in views:
            if view.trend:
                values = [watch.read_or_none(t, cpu) for t in view.trend]
                sample = TrendSample(scan=cpu.scans, time_ms=cpu.time_ms, values=values)
                view.samples.append(sample)
                view.history.append(sample)

    # -- snapshots -------------------------------------------------------------------------------
    def cpu_state(self) -> CpuState:
        cpu = self.cpu
        stats = self._stats
        cycle = (
            CycleStats(
                last_ms=round(stats[0], 4),
                min_ms=round(stats[1], 4),
                max_ms=round(stats[2], 4),
                avg_ms=round(stats[3] / stats[4], 4),
            )
            if stats
            else None
        )
        mode = "HOLD" if self.held is not None else cpu.mode
        engine = cpu.engine
        forced = [
            ForcedValue(address=f"{area}{byte}.{bit}", value=value)
            for area, table in (("I", engine.forced_inputs), ("Q", engine.forced_outputs))
            for (byte, bit), value in sorted(table.items())
        ]
        return CpuState(
            mode=mode,
            time_mode=self.time_mode,
            cycle_ms=cpu.cycle_ms,
            scans=cpu.scans,
            time_ms=cpu.time_ms,
            stop_code=cpu.stop_code,
            stop_reason=cpu.stop_reason,
            cycle=cycle,
            forced=forced,
        )

    def _publish(self, force: bool = False) -> None:
        if not self.clients:
            return
        now = time.perf_counter()
        if not force and not self._urgent and now < self._next_publish:
            return
        if now >= self._next_publish:  # ~30 a second on average, whatever the cycle time
            self._next_publish = max(self._next_publish + FRAME_INTERVAL_S, now)
        self._urgent = False
        self._stale = False
        values: dict[str, WatchValue] = {}
        for view in list(self.clients.values()):
            for text, target in view.watch_targets.items():
                if text not in values:
                    values[text] = watch.watch_value(text, target, self.cpu, self.held)
        self._seq += 1
        self.snapshot = Snapshot(
            self._seq,
            self.cpu_state(),
            values,
            dict(self._block_status),
            self.hold_view,
            self.engine.diagnostic_count,
            None if self.plant is None else self.plant.frame_view(),
        )
        emit = self.emit
        if emit is None:
            return
        snapshot = self.snapshot
        for client, view in list(self.clients.items()):
            frame = view.state.frame(snapshot, view, self)
            if frame is not None:
                emit(client, frame.model_dump_json())


def _base_name(path: str) -> str:
    return path.replace("\\", "/").rsplit("/", 1)[-1].casefold()


def _pairs(sources: list[SourceFile]) -> list[tuple[str, str]]:
    return [(f.name, f.text if isinstance(f.text, str) else f.text.decode()) for f in sources]


def _cpu(program: Any, properties: CpuProperties, profile: Profile, cycle_ms: float) -> Cpu:
    options = properties.cpu_options() | {"profile": profile}
    try:
        return Cpu(program, cycle_ms=cycle_ms, **options)
    except ValueError:  # e.g. a clock memory byte the chosen profile lacks: the file's check says
        return Cpu(program, profile, cycle_ms)
