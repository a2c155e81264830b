"""Several agents in one run, talking with Jason's performatives.

:class:`MultiAgentSystem` steps its agents in a fixed order (one reasoning cycle each
per round), delivers messages to mailboxes (one message is taken in per cycle, as in
Jason) and shares one virtual clock for ``.wait``. What a message does to its receiver
is in :mod:`robocog.bdi.messages`.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from robocog.bdi.agent import Agent
from robocog.bdi.logic import ActionError
from robocog.bdi.messages import Message
from robocog.bdi.terms import Literal, Term, term_str

__all__ = ["Message", "MultiAgentSystem"]


def _text(t: Term | None) -> str | None:
    return t if t is None or t.__class__ is str else term_str(t)


class MultiAgentSystem:
    """Agents that run together and can send each other messages."""

    def __init__(self, environment: Callable[[str, Literal], Any] | None = None) -> None:
        self.agents: dict[str, Agent] = {}
        self.environment = environment
        self.stopped = False
        self.clock = 0.0
        #: the agents that may have something to do, by name, with their place in the
        #: order: an agent that is idle and waits for nothing sleeps until a message
        #: or a change from outside wakes it, so a round costs what the awake ones do
        self._awake: dict[str, int] = {}
        self._place: dict[str, int] = {}
        #: known to have work for the next round: an agent was left busy by its step or
        #: was sent news (agents only ever give each other work, never take it away),
        #: so run() need not ask every awake agent whether it is idle
        self._busy = False
        self._env_version: int | None = None
        #: when ``.stopMAS(T)`` ends the run (clock milliseconds)
        self._stop_at: float | None = None
        #: the directory facilitator: (agent, service, type) in registration order
        self._df: dict[tuple, None] = {}
        self._df_subs: list[tuple] = []

    def add(self, agent: Agent) -> Agent:
        """Add an agent (its name must be unique)."""
        if agent.name in self.agents:
            raise ValueError(f"there is already an agent named {agent.name}")
        agent.mas = self
        self.agents[agent.name] = agent
        self._place[agent.name] = len(self._place)
        self._awake[agent.name] = self._place[agent.name]
        return agent

    def shut_down(self, deadline_ms: float) -> None:
        """``.stopMAS(T)``: every agent that is not asleep gets ``+jag_shutting_down(T)``;
        the system stops when those are handled (no intention left for them and no
        other work but timers) or after T milliseconds."""
        from robocog.bdi.circumstance import Event
        from robocog.bdi.plans import BELIEF, Trigger

        trig = Trigger("+", BELIEF, Literal("jag_shutting_down", (deadline_ms,)))
        for ag in list(self.agents.values()):
            if not ag.sleeping:
                ag.post(Event(trig, None))
                self.wake(ag)
        self._stop_at = self.clock + deadline_ms

    def remove(self, name: str) -> Agent | None:
        """Take the agent named ``name`` out of the system (``.kill_agent``)."""
        ag = self.agents.pop(name, None)
        self._awake.pop(name, None)
        self._place.pop(name, None)
        if ag is not None:
            ag.mas = None
            self._df = {k: v for k, v in self._df.items() if k[0] != name}
        return ag

    # ---- the directory facilitator: who offers which service
    # services are named by their text, as in Jason (``initiator`` and ``"initiator"``
    # are the same service)
    def df_register(self, agent: str, service: Term, kind: Term | None) -> None:
        """``agent`` offers ``service``; subscribers to it are told ``provider(...)``."""
        key = (agent, _text(service), _text(kind))
        if key in self._df:
            return
        self._df[key] = None
        for sub, s_service, s_kind in list(self._df_subs):
            if _text(s_service) == key[1] and (s_kind is None or _text(s_kind) == key[2]):
                self._tell_provider(sub, agent, s_service)

    def df_deregister(self, agent: str, service: Term, kind: Term | None) -> None:
        """``agent`` no longer offers ``service``."""
        name = _text(service)
        for key in [k for k in self._df if k[0] == agent and k[1] == name]:
            if kind is None or key[2] == _text(kind):
                del self._df[key]

    def df_search(self, service: Term, kind: Term | None) -> list[str]:
        """The agents that offer ``service`` (of ``kind``), in the order they registered."""
        name, kname = _text(service), _text(kind)
        out: list[str] = []
        for ag, s_service, s_kind in self._df:
            if s_service == name and (kind is None or s_kind == kname) and ag not in out:
                out.append(ag)
        return out

    def df_subscribe(self, agent: str, service: Term, kind: Term | None) -> None:
        """Tell ``agent`` of every provider of ``service``, now and later."""
        self._df_subs.append((agent, service, kind))
        for provider in self.df_search(service, kind):
            self._tell_provider(agent, provider, service)

    def _tell_provider(self, agent: str, provider: str, service: Term) -> None:
        content = Literal("provider", (Literal(provider), service))
        self.deliver(Message("df", agent, "tell", content, f"df{len(self._df)}"))

    def wake(self, agent: Agent) -> None:
        """Let ``agent`` run in the next rounds (it has news)."""
        if agent.name in self._place:
            self._awake[agent.name] = self._place[agent.name]
            self._busy = True

    def create(self, name: str, source: str = "", **kw: Any) -> Agent:
        """Build an agent from source text and add it."""
        return self.add(Agent(source, name, **kw))

    def create_from_file(self, path: str | Path, name: str | None = None, **kw: Any) -> Agent:
        """Build an agent from an ``.asl`` file and add it."""
        return self.add(Agent.from_file(path, name, **kw))

    def deliver(self, msg: Message) -> None:
        """Put a message in its receiver's mailbox."""
        ag = self.agents.get(msg.receiver)
        if ag is None:
            raise ActionError(f"no agent named {msg.receiver}")
        ag.mailbox.append(msg)
        place = self._place.get(ag.name)
        if place is not None:  # wake it (as wake() does)
            self._awake[ag.name] = place
            self._busy = True

    def step(self) -> None:
        """One reasoning cycle of every agent, in the order they were added."""
        awake = self._awake
        agents = self.agents
        env = self.environment
        version = getattr(env, "version", None)
        if version is not None and version != self._env_version:
            # an Environment's percepts changed: every agent perceives them next
            self._env_version = version
            for ag in list(agents.values()):
                ag.set_percepts(env.percepts(ag.name))
                self.wake(ag)
        order = sorted(awake, key=awake.__getitem__) if len(awake) > 1 else list(awake)
        clock = self.clock
        for name in order:
            ag = agents.get(name)
            if ag is None:
                awake.pop(name, None)
                continue
            ag.clock = clock
            ag.step()
            if not ag.is_idle():
                self._busy = True
            elif not ag.has_pending() and ag.next_timer() is None:
                del awake[name]  # asleep until news wakes it

    def is_idle(self) -> bool:
        """True when no agent has anything to do now."""
        version = getattr(self.environment, "version", None)
        if version is not None and version != self._env_version:
            return False  # the environment's percepts changed: news for the agents
        # a sleeping agent is idle: it went to sleep so, and nothing has woken it
        agents = self.agents
        for name in self._awake:
            ag = agents.get(name)
            if ag is not None and not ag.is_idle():
                return False
        return True

    def run(
        self,
        max_rounds: int | None = None,
        real_time: bool = False,
        until: Callable[[], bool] | None = None,
    ) -> int:
        """Run rounds until every agent is idle.

        ``real_time``: the shared clock of ``.wait``, ``.at``, deadlines and reply
        timeouts is the wall clock, as in Jason, so an agent that is busy does not stop
        the others' clocks; when all are idle the system sleeps until the first timer.
        Otherwise the clock is virtual: it stands still during a round and jumps to the
        next timer when all are idle, so a run is the same on any machine (what
        reproducible experiments need). ``until``: a test made between rounds that ends
        the run when it is true."""
        n = 0
        mono = time.monotonic
        t0 = mono()
        base = self.clock
        while not self.stopped and (max_rounds is None or n < max_rounds):
            if until is not None and until():
                break
            if real_time:
                self.clock = base + (mono() - t0) * 1000.0
            if self._stop_at is not None and (self.clock >= self._stop_at or self.is_idle()):
                break  # .stopMAS(T): shutting down handled, or its time is up
            if self._busy:
                self._busy = False
            elif self.is_idle():
                timers = [t for ag in self.agents.values() if (t := ag.next_timer()) is not None]
                if not timers and real_time and any(a.has_pending() for a in self.agents.values()):
                    # an action outcome or a reply is on its way (from another thread)
                    time.sleep(0.005)
                    continue
                if timers and real_time:
                    due = min(timers)
                    if due > self.clock:
                        time.sleep(min(0.05, (due - self.clock) / 1000.0))
                    self.clock = base + (mono() - t0) * 1000.0
                    for ag in self.agents.values():
                        ag.clock = self.clock
                    if due > self.clock:
                        continue
                    self.step()
                    n += 1
                    continue
                if timers:
                    self.clock = max(self.clock, min(timers))
                    for ag in self.agents.values():
                        ag.clock = self.clock
                    continue
                break
            self.step()  # sets _busy again when there is work left
            n += 1
        return n
