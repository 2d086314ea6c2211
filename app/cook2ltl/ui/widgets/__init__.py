"""Widgets of the app's screens; each draws one kind of core record."""
