"""``robocog sim tabletop --physics``: the physical tabletop on its own, driven by commands.

No mind here (the simulator knows no engine): the operator's commands, by default the
four steps of Table 5.2 that build BlockA on the workbench (Fig. 5.7), go to the arm
one by one; each outcome is printed, then what the cameras see. ``--perturb`` moves a
cube by hand halfway through, so a later command meets a changed scene (to see a mind
replan around such a change, run ``robocog experiment assembly --world mujoco
--perturb``). The run is filmed to an animated GIF, with a key frame of the end.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from robocog.robot.commands import Command, PickUp, PutDown, Stack, Unstack
from robocog.robot.percepts import Resting

DEFAULT_SCRIPT = (
    "PickUp BettClamp; Stack BettClamp workbench; "
    "PickUp InductionHardenedRod; Stack InductionHardenedRod BettClamp"
)
MAX_COMMANDS = 200


def parse_script(text: str) -> list[Command]:
    """``"PickUp A; Stack A B; ..."`` as Commands (ValueError naming a bad one)."""
    kinds = {"pickup": PickUp, "putdown": PutDown, "stack": Stack, "unstack": Unstack}
    arity = {"pickup": (1,), "putdown": (1, 2), "stack": (2,), "unstack": (2,)}
    out: list[Command] = []
    for i, part in enumerate(p.strip() for p in text.split(";")):
        if not part:
            continue
        words = part.split()
        kind = words[0].lower().replace("-", "").replace("_", "")
        if kind not in kinds or len(words) - 1 not in arity[kind]:
            raise ValueError(f"command {i + 1} ({part!r}): expected e.g. 'PickUp A' or 'Stack A B'")
        out.append(kinds[kind](*words[1:]))
        if len(out) > MAX_COMMANDS:
            raise ValueError(f"more than {MAX_COMMANDS} commands")
    return out


#: wall seconds to build the scene and to run one command, on this project's 2-core
#: machine (rendering the cameras and finding the tags take most of it)
SETUP_SECONDS = 3.0
COMMAND_SECONDS = 2.0


def run_tabletop(args: argparse.Namespace) -> int:
    """Run the commands on the physical tabletop and film it."""
    if not args.physics:
        print("robocog sim tabletop: only --physics is served here", file=sys.stderr)
        return 2
    try:
        commands = parse_script(args.do)
    except ValueError as exc:
        print(f"robocog sim tabletop: {exc}", file=sys.stderr)
        return 2
    try:
        import imageio.v3 as iio

        from robocog.worlds.mujoco_tabletop import MujocoTabletop
    except ImportError as exc:
        print(f"robocog sim tabletop: needs the physics extra ({exc})", file=sys.stderr)
        return 2
    from rich.console import Console

    from robocog.progress import Steps, duration, header

    console = Console()
    header(
        console,
        "robocog sim tabletop --physics",
        f"{len(commands)} operator commands run by the MuJoCo arm"
        + (", a cube moved by hand halfway" if args.perturb else "")
        + ("" if args.no_video else ", filmed to a GIF"),
        f"{duration(SETUP_SECONDS + COMMAND_SECONDS * len(commands))} on an idle machine",
    )
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    failures = 0
    with Steps(console) as steps:
        task = steps.add("commands", len(commands))
        steps.note(task, "building the scene")
        world = MujocoTabletop(seed=args.seed, record=not args.no_video)
        world.frame_every = 0.5
        start = time.perf_counter()
        for i, command in enumerate(commands):
            if args.perturb and i == len(commands) // 2:
                steps.say(f"  by hand: {world.perturb()}")
            steps.note(task, str(command))
            outcome = world.execute(command)
            failures += not outcome.ok
            steps.say(f"{world.time():6.1f} s  {command}: {'ok' if outcome.ok else outcome.reason}")
            steps.advance(task)
    seen = [p for p in world.percepts() if isinstance(p, Resting)]
    wall = time.perf_counter() - start
    print("the cameras see: " + ", ".join(f"{p.obj} on {p.on}" for p in seen))
    print(
        f"{world.time():.0f} s simulated in {wall:.1f} s (x{world.time() / wall:.1f} real time), "
        f"{world.looks} looks"
    )
    if not args.no_video:
        iio.imwrite(out / "tabletop.png", world.snapshot())
        if world.frames:
            iio.imwrite(
                out / "tabletop.gif", [f[::2, ::2] for f in world.frames], duration=125, loop=0
            )
        print(f"film: {out / 'tabletop.gif'}, last frame: {out / 'tabletop.png'}")
    world.close()
    return 1 if failures else 0
