"""AgentSpeak(L) with Jason's semantics: parser, unifier, belief base with rules,
plan library, intentions and the reasoning cycle, plus Jason's standard internal actions.

Typical use::

    from robocog.bdi import Agent
    ag = Agent(open("robot.asl").read(), "robot")
    ag.register_action("forward", lambda d: robot.forward(d))
    ag.add_percept("obstacle(front)")
    ag.run()
"""

from robocog.bdi.actions import ActionHandle, from_python, to_python
from robocog.bdi.agent import Agent
from robocog.bdi.mas import Message, MultiAgentSystem
from robocog.bdi.parser import ParseError, parse_literal, parse_plan, parse_program, parse_term
from robocog.bdi.terms import Literal, Var, term_str

__all__ = [
    "ActionHandle",
    "Agent",
    "Literal",
    "Message",
    "MultiAgentSystem",
    "ParseError",
    "Var",
    "from_python",
    "parse_literal",
    "parse_plan",
    "parse_program",
    "parse_term",
    "term_str",
    "to_python",
]
