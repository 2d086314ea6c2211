"""What every stage speaks: a recipe's steps, spans and frames (`recipe`), actions, calls, primitive sets and
reductions (`actions`), and the user's settings (`settings`, read by `settings_file`, checked by
`settings_schema`)."""
