"""Load capacity: tooth rating (ISO 6336), bearing life (ISO 281) and duty cycles."""
