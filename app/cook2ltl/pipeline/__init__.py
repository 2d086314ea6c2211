"""Algorithm 1 over a whole recipe (`translator`), what it produces (`records`), and how that is shown:
JSON (`serialize`), text (`report`), rates (`rates`), and a rollout of the recipe in the world model
(`world_rollout`)."""
