"""The app's screens: Translate, Library and Rollout (one per mode), and the dialogs they open."""
