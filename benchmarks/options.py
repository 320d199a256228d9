"""Command-line options shared by the benchmark scripts."""
import sys


def take_option(arguments, name, convert=str, default=None):
    """Removes '--name value' from the list arguments and returns
    convert(value), or default if the option is not there; exits with a
    message naming the option if its value is missing or invalid."""
    if name not in arguments:
        return default
    k = arguments.index(name)
    try:
        value = convert(arguments[k + 1])
    except (IndexError, ValueError):
        sys.exit("%s needs a value (%s)" % (name, convert.__name__))
    del arguments[k:k + 2]
    return value
