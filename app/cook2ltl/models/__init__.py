"""The model stack: a manifest in models/models.toml, a per-user cache, provisioning and checks."""
