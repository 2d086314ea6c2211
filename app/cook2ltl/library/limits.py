"""How much the library takes from a file a user gives it. Each bound is far above what cook2ltl itself writes,
and keeps a hostile file from filling the memory, the disk or the screen."""

EXPORT_BYTES = 32 * 2**20  # an export file to import
BODY_BYTES = 20_000  # a body, from `library edit --body-file` or an export (one call a line: a few hundred lines)
ENTRIES = 100_000  # entries in one export file
VERSIONS = 10_000  # versions, and reviews, of one entry
VERSION_NUMBER = 10**9  # the largest version number
NAME_CHARS = 200  # a primitive set, verb, model, author, reviewer, prompt hash, example value or time
MESSAGE_CHARS = 2_000  # a kitchen-check problem or a version's note
PROBLEMS = 1_000  # problems of one kitchen check
SLOTS = 32  # slots of one signature, placeholders of one example
ATOMS = 100  # atoms of one intended effect
