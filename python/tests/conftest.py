import sys
from pathlib import Path

# rows.py (shared test data) is imported by the tests and by python/bench.py.
sys.path.insert(0, str(Path(__file__).resolve().parent))
