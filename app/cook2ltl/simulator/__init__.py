"""The embedded THOR-compatible kitchen: a leaf that only speaks AI2-THOR's FIFO protocol.

`scenes` (the 30 kitchens from assets/kitchens/), `state` and `rules` (THOR's interaction rules as a pure
state machine), `agent`, `metadata` and `session` (THOR-shaped events), `protocol` and `player` (the
executable ai2thor's own Controller launches). It imports nothing of the pipeline; the robot side
(`execution`) drives it, or a real THOR build, through the Controller.
"""
