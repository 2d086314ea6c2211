"""An embedded, THOR-compatible kitchen and the launcher for it or a real AI2-THOR build.

Modules: `scenes` (the 30 kitchens from assets/kitchens/), `state` and `rules`
(THOR's interaction rules as a pure state machine), `metadata` and `session`
(THOR-shaped events), `protocol` and `player` (the FIFO executable the
Controller launches), `launcher` (start a Controller on either backend).
Only `launcher` imports ai2thor.
"""
