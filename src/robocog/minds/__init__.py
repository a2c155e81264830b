"""Adapters between an engine and the robot contract: percepts become engine
input, engine operations become Commands. The only package that knows both sides.
"""
