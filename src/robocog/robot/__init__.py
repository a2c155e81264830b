"""The robot contract shared by every mind and every body: percept and command
types, the Body and Mind protocols, and the sense-decide-act loop. Knows no engine.
"""
