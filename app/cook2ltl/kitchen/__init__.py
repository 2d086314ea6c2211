"""An embedded, THOR-compatible kitchen and the launcher for it or a real AI2-THOR build.

Modules: `scenes` (the 30 kitchens from assets/kitchens/), `state` and `rules`
(THOR's interaction rules as a pure state machine), `metadata` and `session`
(THOR-shaped events), `protocol` and `player` (the FIFO executable the
Controller launches), `launcher` (start a Controller on either backend).

Rollouts through the Controller: `names` (plan names to objectIds), `facts`
(state predicates from metadata), `executor` (one primitive atom as THOR
actions), `rollout` (a formula executed with LTL progression after every
action), `tasks` (assets/tasks/ and goal conditions), `planning` (a task's
instruction through Algorithm 1), `trial` (one task or formula, start to goal).
Only `launcher` imports ai2thor.
"""
