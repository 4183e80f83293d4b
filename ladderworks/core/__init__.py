"""The Qt-free core: addresses, instructions, language, ladder model, compiler and engine."""
