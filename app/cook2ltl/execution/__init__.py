"""The robot side: plans run through ai2thor's own Controller, on a real THOR build or the embedded kitchen.

`launcher` and `controller` (start and guard a kitchen), `executor` (one primitive as THOR actions),
`rollout` (a formula executed with LTL progression after every action), `tasks` (assets/tasks/ and their
goal conditions), `kitchen_check` and `plan_run` (a new reduction run line by line before it is cached).
Only `controller` imports ai2thor, and only when a kitchen starts.
"""
