"""The reasoner's public face: input, cycles, questions, operations and persistence.

``NAR`` is a :class:`~robocog.nars.state.Reasoner` (all of its state, declared there)
with the methods a caller uses, as ONA's ``NAR.c`` is over its memory: a line of input
is read here and handed to the functions that do the work (``memorize`` stores an
event, ``cycle`` runs cycles in ONA's order of work, ``questions`` answers, ``commands``
runs a ``*`` line, ``memfile`` saves and loads). Its output lines are ONA's, so a
transcript can be compared with ONA's.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from functools import partial

from . import commands, cycle, memfile, memorize, questions, sensorimotor
from . import truth as tf
from .config import MAX_TIME, Config
from .event import ETERNAL, GOAL, Event
from .inference import rule_table
from .memory import Concept
from .narsese import MAX_LINE, NarseseError, Sentence, parse_sentence
from .state import DEFAULT_OPERATIONS, Reasoner, clear, clear_caches, emit
from .state import rand as _rand
from .terms import Term, atom, sweep_early

#: the most cycles one input line may ask for (a bare number): ONA's examples ask for
#: a thousand at most; a hundred million is hours of work, so more is a typo
MAX_CYCLES_PER_LINE = 100_000_000
#: a cycles line runs in slices of this many cycles, asking ``NAR.stop_requested``
#: between them (a hundred cycles of a full memory take a few tenths of a second)
CYCLE_SLICE = 100


class NAR(Reasoner):
    """A Non-Axiomatic Reasoner with ONA's behaviour and a bounded memory."""

    #: asked between slices of a cycles line; true ends the line early (the shell sets
    #: it to stop on SIGINT and SIGTERM, the inspector's console to its stop command)
    stop_requested: Callable[[], bool] | None = None
    #: the next line of input, None at its end: where an operation marked with
    #: ``*setopstdin`` reads its result (the shell sets it to the rest of its input)
    read_input: Callable[[], str | None] | None = None

    def __init__(self, seed: int = 666, ona: str = "0.9.2", **config_overrides: object) -> None:
        # ``ona``: whose behaviour to follow, ONA 0.9.2's (the papers') or 0.9.3's
        Reasoner.__init__(self, Config.for_ona(ona, **config_overrides), seed)
        self.memory.on_remove = partial(sensorimotor.forget_concept, self)
        # the rule table, shared by the process's reasoners, is built here if it is not
        # yet: building it takes tens of milliseconds, which would stall a robot's first
        # reasoning cycle
        rule_table(self.config.semantic_inference_nal_level, self.config.plain_conjunctions)

    # ------------------------------------------------------------------ state
    def reset(self) -> None:
        """Forget everything (ONA's ``*reset``); the random generator is not reseeded."""
        clear(self)
        for name, fn in list(self.operations.items()):
            del self.operations[name]
            self.register_operation(name, fn)  # type: ignore[arg-type]
        self.memory.on_remove = partial(sensorimotor.forget_concept, self)

    def random_state(self) -> int:
        """The random generator's state, as a saved memory keeps it."""
        return self.rand_state

    def set_random_state(self, state: int) -> None:
        """Continue the random sequence from ``state`` (a value of :meth:`random_state`)."""
        if not -(1 << 63) <= state < 1 << 64:
            raise ValueError(f"a random state is in [-2**63, 2**64), not {state}")
        self.rand_state = state

    def rand(self) -> int:
        """ONA's ``myrand``: the POSIX example LCG, 0..32767."""
        return _rand(self)

    # --------------------------------------------------------------- callbacks
    def on_answer(self, cb: Callable[[Event], None]) -> None:
        """Call ``cb(event)`` with every answer found."""
        self.answer_cbs.append(cb)

    def on_derivation(self, cb: Callable[[Event], None]) -> None:
        """Call ``cb(event)`` with every derived event that enters the event queue."""
        self.derivation_cbs.append(cb)

    def on_execution(self, cb: Callable[[str, Term | None], None]) -> None:
        """Call ``cb(op_name, argument)`` whenever an operation is executed."""
        self.execution_cbs.append(cb)

    def register_operation(self, name: str, fn: Callable[[Term | None], object]) -> None:
        """Make ``name`` (e.g. ``^pick``) executable, calling ``fn(argument)`` when it is.

        What ``fn`` returns is ignored, except that a term is the operation's result
        where its argument ``({SELF} * X)`` has variables (``X`` is unified with it, as
        ONA's ``*setopstdin`` operations do), and that False, in a compound operation,
        means it failed and the rest is not run."""
        if not name.startswith("^"):
            raise ValueError(f"operation names start with '^': {name!r}")
        if name not in self.op_names:
            # take the first of ONA's default (no-op) slots nobody registered yet
            free = [
                i
                for i, n in enumerate(self.op_names)
                if n in DEFAULT_OPERATIONS and n not in self.operations
            ]
            if free:
                self.op_names[free[0]] = name
            elif len(self.op_names) < self.config.operations_max:
                self.op_names.append(name)
            else:
                raise ValueError(f"no free operation slot for {name}")
        self.operations[name] = fn

    def emit(self, line: str) -> None:
        """Write one output line (to ``output``, if set), as the reasoner's own are."""
        emit(self, line)

    def name_operation(self, k: int, name: str) -> None:
        """ONA's ``*setopname k name``: operation ``k`` (1-based) is called ``name``."""
        if not 1 <= k <= self.config.operations_max:
            raise ValueError(
                f"operation number {k} is out of range [1, {self.config.operations_max}]"
            )
        if not name.startswith("^"):
            raise ValueError("operation names start with '^'")
        names = list(self.op_names)
        while len(names) < k:
            names.append(f"^op{len(names) + 1}")
        names[k - 1] = name
        self.op_names = [n for i, n in enumerate(names) if i < k or n != name]

    def op_id(self, op: Term) -> int:
        """1-based id of the operation ``op`` (``^name`` or ``<args --> ^name>``); 0 if unknown."""
        return sensorimotor.op_id(self, op)

    # ------------------------------------------------------------------ input
    def add_input(self, text: str) -> None:
        """One Narsese line or shell command; bad input raises :class:`NarseseError`
        and leaves the reasoner as it was."""
        line = text.strip()
        if not line:
            cycle.cycles(self, 1)
            return
        if line.startswith("//"):
            emit(self, "Comment: " + line[2:])
            return
        if len(line) > MAX_LINE:
            raise NarseseError(1, MAX_LINE + 1, f"line longer than {MAX_LINE} characters")
        if line.isdigit():
            if not line.isascii():
                raise NarseseError(1, 1, "a number of cycles is written in digits 0-9")
            n = int(line) if len(line) <= 12 else MAX_CYCLES_PER_LINE + 1
            if n > MAX_CYCLES_PER_LINE:
                raise NarseseError(1, 1, f"at most {MAX_CYCLES_PER_LINE} cycles per line")
            if n and self.time >= MAX_TIME:
                raise NarseseError(1, 1, f"the reasoner's time has reached {MAX_TIME}; *reset")
            emit(self, f"performing {n} inference steps:")
            done = 0
            while done < n:
                # in slices, asking between them whether to stop (a signal to the
                # shell, a stop button): a long line ends within a slice's time
                k = min(n - done, CYCLE_SLICE)
                cycle.cycles(self, k)
                done += k
                stop = self.stop_requested
                if stop is not None and done < n and stop():
                    break
            emit(self, f"done with {done} additional inference steps.")
            return
        if line.startswith("*"):
            self._command(line)
            return
        self.add_sentence(parse_sentence(line))

    def add_sentence(self, s: Sentence) -> None:
        """Enter a parsed sentence: beliefs and goals run one cycle, questions are answered."""
        if self.time >= MAX_TIME:
            raise NarseseError(1, 1, f"the reasoner's time has reached {MAX_TIME}; *reset")
        if self.stamp_base >= MAX_TIME and s.punctuation != "?":
            raise NarseseError(1, 1, f"the stamp ids have reached {MAX_TIME}; *reset")
        if s.punctuation == "?":
            questions.answer(self, s.term, s.tense)
            return
        if s.tense is None and s.punctuation == GOAL:
            raise NarseseError(1, 1, "eternal goals are not supported; add ':|:'")
        if s.tense not in (None, ":|:"):
            raise NarseseError(1, 1, "only present-tense events (':|:') can be input")
        t = s.truth or tf.DEFAULT
        occ = ETERNAL if s.tense is None else self.time
        e = Event(
            s.term,
            s.punctuation,
            t,
            (self.stamp_base,),
            occ,
            self.time,
            s.dt or 0.0,
            is_input=True,
        )
        self.stamp_base += 1
        self.stats["inputs"] += 1
        memorize.add_event(self, e, 1.0, is_input=True)
        cycle.cycles(self, 1)

    # ---------------------------------------------------------------- commands
    def _command(self, line: str) -> None:
        """A ``*`` line: see :mod:`robocog.nars.commands` for the table of commands."""
        commands.execute(self, line)

    def concept_line(self, con: Concept) -> str:
        """ONA's ``*concepts`` line for ``con``."""
        b = con.belief
        tv = f" {b.truth}" if b is not None else ""
        return (
            f'//{con.term}: {{ "priority": {memorize.concept_priority(self, con):f}, '
            f'"usefulness": {con.usefulness(self.time):f}, "useCount": {con.use_count}, '
            f'"lastUsed": {con.last_used}}}{tv}'
        )

    def statistics(self) -> list[str]:
        """ONA-style statistics lines."""
        return [
            "Statistics",
            "----------",
            f"currentTime:\t\t\t{self.time}",
            f"total concepts:\t\t\t{len(self.memory)}",
            f"concept capacity:\t\t{self.memory.capacity}",
            f"evicted concepts:\t\t{self.memory.evictions}",
            f"current average concept priority:\t{self._avg_priority():f}",
            f"current belief events cnt:\t\t{len(self.memory.belief_events)}",
            f"total input events:\t\t{self.stats['inputs']}",
            f"total derived events:\t\t{self.stats['derived']}",
            f"total selected events:\t\t{self.stats['selected']}",
            f"total answers:\t\t\t{self.stats['answers']}",
            f"distinct names:\t\t\t{len(self.memory.atom_index)}",
        ]

    def _avg_priority(self) -> float:
        n = len(self.memory)
        return sum(memorize.concept_priority(self, c) for c in self.memory) / n if n else 0.0

    # ------------------------------------------------------------------ cycle
    def cycles(self, n: int) -> None:
        """Run ``n`` inference cycles."""
        cycle.cycles(self, n)

    def tidy(self) -> int:
        """Do between a robot's cycles the upkeep that would otherwise pause one: sweep
        the process's term table of terms nobody holds once it is half-way to the size
        at which making a term would sweep it (:func:`terms.sweep_early`). Reasoning is
        unchanged by it. Returns how many terms went."""
        return sweep_early()

    # -------------------------------------------------------------- questions
    def answer(self, question: Term, tense: str | None = None) -> Event | None:
        """Answer a question at once with the best belief, printing ONA's lines."""
        return questions.answer(self, question, tense)

    def ask(self, question: str) -> Event | None:
        """Answer a question given as text, e.g. ``"<a --> ?1>?"``."""
        s = parse_sentence(question.strip())
        if s.punctuation != "?":
            raise NarseseError(1, len(question.strip()), "a question ends with '?'")
        return questions.answer(self, s.term, s.tense)

    # ------------------------------------------------------------ persistence
    def save(self, path: str | os.PathLike[str]) -> None:
        """Write the whole memory to ``path`` as a memory file (``memfile``): atomically,
        mode 0600, never over a file that is not a robocog memory."""
        memfile.write_file(path, memfile.encode(self))

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> NAR:
        """A reasoner restored from a file written by :meth:`save`; a file that is not
        one, or that is damaged, raises :class:`memfile.MemoryFileError` (one line)."""
        snap = memfile.load_file(path)
        nar = cls(seed=snap.seed)
        nar._take(snap)
        return nar

    def restore(self, path: str | os.PathLike[str]) -> None:
        """Replace this reasoner's state by the one saved at ``path`` (``*load``); the
        output, callbacks and registered operations stay. A refused file changes
        nothing."""
        snap = memfile.load_file(path)
        self._take(snap)

    def _take(self, snap: memfile.Snapshot) -> None:
        for k, v in snap.config.items():
            setattr(self.config, k, v)
        self.seed = snap.seed
        self.rand_state = snap.rand
        self.memory = snap.memory
        self.time = snap.time
        self.stamp_base = snap.stamp_base
        self.concept_threshold = snap.concept_threshold
        self.matched_total = snap.matched_total
        self.process_id = snap.process_id
        self.op_names = snap.op_names
        self.stats = snap.stats
        self.pending_questions = snap.pending_questions
        # the sensorimotor indexes' caches start empty, as they do after a reset
        clear_caches(self)
        self.time_index = snap.time_index
        self.table_index = snap.table_index
        self.links_by_subject = snap.links_by_subject
        self.general_links = snap.general_links
        self.goal_layers = snap.goal_layers
        self.recent_goal_concepts = snap.recent_goal_concepts
        self.memory.on_remove = partial(sensorimotor.forget_concept, self)


__all__ = ["NAR", "NarseseError", "atom"]
