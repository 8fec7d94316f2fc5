"""results.h5 and frames.h5 read for report.html, checked where they are read: a file granpipe
did not write so (damaged, edited by hand) raises Damaged, whose message is the one line
report.py prints: "<file>: <object>[ attribute <name>]: expected ..., found ...".

NaN and inf in a dataset of numbers are data (a value the run left undefined), never damage.
Neither h5py nor numpy is imported here: report.py lists the CSV files without them."""
import json
import numbers
import os
import stat

REQUIRED = object()  # attr_text's default: the attribute must be there
NUMBER_KINDS = "iuf"  # numpy dtype kinds of the numbers granpipe writes (ints, floats)


class Damaged(Exception):
    """A results or frames file that is not as granpipe writes it; str() is the message."""


# What h5py raises for an object HDF5 cannot read (a flipped byte, a heap cut short): caught
# where a file is read, and turned into Damaged by unreadable when h5py raised it.
HDF5_ERRORS = (KeyError, OSError, RuntimeError)


def unreadable(path, error, what="results"):
    """A Damaged for the granpipe `what` file `path`, part of which HDF5 could not read
    (`error`, one of HDF5_ERRORS); `error` itself when h5py did not raise it (a bug of ours
    stays a traceback)."""
    tb, innermost = error.__traceback__, ""
    while tb is not None:
        innermost, tb = tb.tb_frame.f_code.co_filename, tb.tb_next
    if "h5py" not in innermost.replace("\\", "/").split("/"):
        raise error
    reason = " ".join(str(error.args[0] if error.args else error).split())
    return Damaged(f"{path}: expected a granpipe {what} file, found one HDF5 cannot read: "
                   f"{reason}")


def damaged(obj, expected, found, attr=None, path=None):
    """A Damaged for the object `obj` (or the member `path` of it) or its attribute `attr`."""
    where = path or obj.name
    if attr:
        where += f" attribute {attr}"
    return Damaged(f"{obj.file.filename}: {where}: expected {expected}, found {found}")


def shown(value):
    """A value found, short and on one line: text quoted, bytes that are not UTF-8 escaped."""
    if isinstance(value, bytes):
        value = value.decode(errors="backslashreplace")
    if isinstance(value, str):
        return json.dumps(value if len(value) <= 40 else value[:40] + "…", ensure_ascii=False)
    if hasattr(value, "shape") and value.shape != ():
        of = "text" if value.dtype.kind in "SUO" else value.dtype
        return f"an array of {of} of shape {value.shape}"
    return str(value)


def decoded(obj, attr, value):
    """`value` as a str, None when it is no text; text that is not UTF-8 is damage."""
    if isinstance(value, str):
        return str(value)
    if not isinstance(value, bytes):
        return None
    try:
        return bytes(value).decode()
    except UnicodeDecodeError as e:
        raise damaged(obj, "UTF-8 text", f"byte 0x{e.object[e.start]:02x} at offset {e.start}, "
                      "which is not UTF-8", attr) from None


def attribute(obj, name, what):
    """The attribute's value, which must be there (`what` says what it should be)."""
    if name not in obj.attrs:
        raise damaged(obj, what, "none", name)
    return obj.attrs[name]


def attr_text(obj, name, default=REQUIRED):
    """A text attribute; absent: `default` where one is given."""
    if default is not REQUIRED and name not in obj.attrs:
        return default
    value = attribute(obj, name, "text")
    text = decoded(obj, name, value)
    if text is None:
        raise damaged(obj, "text", shown(value), name)
    return text


def attr_texts(obj, name, length=None, why=""):
    """A list of text (column names, units); of `length` items (`why` says why) when given."""
    value = attribute(obj, name, "a list of text")
    if getattr(value, "ndim", None) != 1:
        raise damaged(obj, "a list of text", shown(value), name)
    texts = [decoded(obj, name, v) for v in value]
    if None in texts:
        raise damaged(obj, "a list of text", shown(value), name)
    if length is not None and len(texts) != length:
        raise damaged(obj, f"{length} items ({why})", len(texts), name)
    return texts


def attr_number(obj, name, integer=False):
    """A number attribute (an integer where `integer`), as h5py gives it."""
    value = attribute(obj, name, "a number")
    if not isinstance(value, numbers.Integral if integer else numbers.Real):
        raise damaged(obj, "an integer" if integer else "a number", shown(value), name)
    return value


def attr_numbers(obj, name, length, why):
    """A list of `length` numbers (`why` says why) as floats."""
    value = attribute(obj, name, "a list of numbers")
    if getattr(value, "ndim", None) != 1 or value.dtype.kind not in NUMBER_KINDS:
        raise damaged(obj, "a list of numbers", shown(value), name)
    if len(value) != length:
        raise damaged(obj, f"{length} numbers ({why})", len(value), name)
    return value.astype(float)


def not_a_file(path):
    """What stands at `path` when it is no regular file (a FIFO, a device, a directory: one
    h5py would block on or fail to read), else None; a symbolic link is followed."""
    mode = os.stat(path).st_mode
    if stat.S_ISREG(mode):
        return None
    for test, what in ((stat.S_ISDIR, "a directory"), (stat.S_ISFIFO, "a FIFO (named pipe)"),
                       (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
                       (stat.S_ISSOCK, "a socket")):
        if test(mode):
            return what
    return "no regular file"


def linked(parent, name):
    """parent[name] where the link `name` is a hard link, as granpipe writes every object: a
    soft or external link (dangling, looping, or into another file) is damage."""
    import h5py
    if name in ("", ".") or "/" in name:  # a path, not one link (HDF5 has no link "." or "")
        return parent[name]
    link = parent.get(name, getlink=True)
    path = f"{parent.name.rstrip('/')}/{name}"
    if isinstance(link, h5py.SoftLink):
        raise damaged(parent, "a group or a dataset", f"a soft link to {shown(link.path)}",
                      path=path)
    if isinstance(link, h5py.ExternalLink):
        raise damaged(parent, "a group or a dataset", "an external link to "
                      f"{shown(link.path)} in {shown(link.filename)}", path=path)
    return parent[name]


def members(group):
    """(name, object) of each member of `group`, its links checked (linked)."""
    return [(name, linked(group, name)) for name in group]


def of_kind(item, kind):
    """`item`, checked to be a "group" or a "dataset"."""
    import h5py
    if not isinstance(item, h5py.Group if kind == "group" else h5py.Dataset):
        raise damaged(item, f"a {kind}", f"a {type(item).__name__.lower()}")
    return item


def member(parent, name, kind):
    """parent[name], a "group" or a "dataset"; each group on a path "a/b" checked on the way."""
    *groups, name = name.split("/")
    for part in groups:
        parent = member(parent, part, "group")
    if name not in parent and (name in ("", ".") or parent.get(name, getlink=True) is None):
        raise damaged(parent, f"a {kind}", "none", path=f"{parent.name.rstrip('/')}/{name}")
    return of_kind(linked(parent, name), kind)


def producer(parent, name):
    """parent[name], a producer's group of results, which granpipe tags with no kind: a result
    found there (a table at the top of the file) would be shown as a heading over nothing."""
    group = member(parent, name, "group")
    kind = attr_text(group, "kind", None)
    if kind is not None:
        raise damaged(group, "a producer (a group of results)", f"a result of kind {shown(kind)}")
    return group


def numbers_dataset(parent, name, ndim, integer=False):
    """parent[name], a dataset of numbers (integers where `integer`) with `ndim` dimensions
    (0: a scalar), not read."""
    ds = member(parent, name, "dataset")
    if ds.dtype.kind not in ("iu" if integer else NUMBER_KINDS):
        found = "text" if ds.dtype.kind in "SUO" else f"values of type {ds.dtype}"
        raise damaged(ds, "integers" if integer else "numbers",
                      found + (f" {shown(ds[()])}" if ds.shape == () else ""))
    if ds.shape is None or ds.ndim != ndim:
        raise damaged(ds, "a scalar" if ndim == 0 else f"{ndim}-D data",
                      "no data (a null dataspace)" if ds.shape is None else f"shape {ds.shape}")
    return ds


# The most values the report reads from one dataset at once (800 MB): a 24 kB results.h5
# whose compressed column declared 1e9 rows ended in a numpy MemoryError, exit 1.
MOST_VALUES = 10**8


def within_reach(ds, values):
    """Refuses to read `values` values of ds beyond MOST_VALUES."""
    if values > MOST_VALUES:
        raise damaged(ds, f"at most {MOST_VALUES:.0e} values to read for the report", values)


def scalar(parent, name):
    """A scalar result, a 0-D dataset of a number."""
    return float(numbers_dataset(parent, name, 0)[()])


def column(group, name, length=None, why=""):
    """A 1-D dataset of numbers as floats; of `length` values (`why` says why) when given."""
    ds = numbers_dataset(group, name, 1)
    within_reach(ds, ds.size)
    values = ds[()].astype(float)
    if length is not None and len(values) != length:
        raise damaged(group[name], f"{length} value{'s' * (length != 1)} ({why})", len(values))
    return values


def still_written(group):
    """Whether the file is a run's results.partial.h5 (marked incomplete): its streamed
    tables grow a column at a time while the run goes."""
    complete = group.file.attrs.get("complete", 1)
    return getattr(complete, "size", 1) == 1 and complete == 0


def read_table(group):
    """(column names, units, {name: values}) of a table: a group of columns of one length.
    In a file still being written the columns are cut to the rows they all have: a row
    reaches them one column at a time, and a report of a running run read some columns a
    row longer than others, and called the file damaged."""
    of_kind(group, "group")
    columns = attr_texts(group, "columns")
    units = attr_texts(group, "units", len(columns), "a unit per column")
    growing = still_written(group)
    data, length = {}, None
    for name in columns:
        data[name] = column(group, name, None if growing else length, f"as many as {columns[0]}")
        length = len(data[columns[0]])
    if growing:
        rows = min((len(values) for values in data.values()), default=0)
        data = {name: values[:rows] for name, values in data.items()}
    return columns, units, data


def indices(group, name, values, count=None):
    """Checks that `values` (of the column `name`) are whole numbers >= 0, below `count`
    when given (the indices of a list of `count` items)."""
    for v in values:
        if not (v.is_integer() and 0 <= v < (count or float("inf"))):  # not NaN, not inf
            expected = f"indices 0 to {count - 1}" if count else "whole numbers >= 0"
            raise damaged(group, expected, shown(v), path=f"{group.name}/{name}")
