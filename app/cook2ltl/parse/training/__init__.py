"""Training and evaluating the span recogniser on the paper's brat annotations."""
