"""The ladder grid editor: scene items, the view with its tools, and the undo commands."""
