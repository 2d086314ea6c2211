"""The Textual app, the owner's surface over the whole pipeline. The core never imports this package."""
