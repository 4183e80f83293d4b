"""The ladder grid editor: the model, the view over it, the tools' interactions, undo commands."""
