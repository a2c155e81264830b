"""AgentSpeak(L) with Jason's semantics: parser, unifier, belief base with rules,
plan library, intentions and the reasoning cycle, plus Jason's standard internal actions.
"""
