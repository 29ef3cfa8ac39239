"""Scenario features beyond the paper (issue 16): roadside lanes, signals and controllers, elevation, overpasses.

Each runs after the paper's stages on the finished layout and document, with its own random stream (derived from the
seed), so switching one on never changes the layout another draws. The "paper" profile turns them all off and the
maps are those of the paper's generator, byte for byte (:data:`junctionart.params.PROFILES`).
"""
