"""armrt's version, apart from __init__ so that modules inside the package (the model cache key) can
read it without importing the package that imports them."""
__version__ = "0.1.0"
