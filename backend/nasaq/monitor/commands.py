"""What each client message does to its session: the call the session's CPU thread carries out."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from nasaq.monitor import protocol as p
from nasaq.monitor.session import Session


def command(session: Session, client: int, message: Any) -> Callable[[], Any]:
    s = session
    match message:
        case p.SubscribeCpu(on=on):

            def subscribe() -> None:
                view = s.view(client)
                view.cpu = on
                view.state.cpu = None  # the next frame carries the whole state

            return subscribe
        case p.Watch(entries=entries):

            def watch() -> dict[str, object]:
                result = s.do_watch(client, entries)
                s.view(client).state.values.clear()
                return result

            return watch
        case p.OpenBlock(block=block, networks=networks):

            def open_block() -> dict[str, object]:
                result = s.do_open_block(client, block, networks)
                s.view(client).state.block_scan = None
                return result

            return open_block
        case p.Trend(entries=entries):
            return lambda: s.do_trend(client, entries)
        case p.SessionState():
            return s.do_session_state
        case p.Run():
            return s.do_run
        case p.Stop():
            return s.do_stop
        case p.Restart(cold=cold):
            return lambda: s.do_restart(cold)
        case p.SetTime(mode=mode, cycle_ms=cycle_ms):
            return lambda: s.do_set_time(mode, cycle_ms)
        case p.SetInput(address=input_address, value=value):
            return lambda: s.do_set_input(input_address, value)
        case p.Modify(target=target, value=value):
            return lambda: s.do_modify(target, value)
        case p.Force(address=forced, value=value):
            return lambda: s.do_force(forced, value)
        case p.Unforce(address=address):
            return lambda: s.do_unforce(address)
        case p.SetBreakpoint(location=location, condition=condition):
            return lambda: s.do_set_breakpoint(location, condition)
        case p.ClearBreakpoint(id=number):
            return lambda: s.do_clear_breakpoint(number)
        case p.Continue():
            return s.do_continue
        case p.Step(by=by, into=into):
            return lambda: s.do_step(by, into)
        case p.RunScans(count=count):
            return lambda: s.do_run_scans(count)
        case p.PlantOperate(control=control, value=value):
            return lambda: s.do_plant_operate(control, int(value))
        case p.PlantFault(fault=fault, on=on):
            return lambda: s.do_plant_fault(fault, on)
        case p.PlantReset():
            return s.do_plant_reset
        case p.GraphControl(db=db, op=op, step=step):
            return lambda: s.do_graph_control(db, op, step)
    raise AssertionError(f"unhandled message {message!r}")
