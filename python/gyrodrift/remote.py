"""Files at fsspec URLs (``s3://bucket/drive.csv.gz``, ``gs://...``, ``memory://...``): the
one place the package fetches bytes that are not on this machine; core parses them."""

from __future__ import annotations


def is_url(spec: str) -> bool:
    """Whether ``spec`` names an fsspec filesystem's file (``s3://...``) rather than a local one."""
    return "://" in spec and not spec.startswith("file://")


def fetch(url: str) -> bytes:
    """The bytes of the file at ``url`` (fsspec; the filesystem's package, e.g. s3fs, installed);
    ``OSError`` naming the URL when it cannot be read."""
    import fsspec

    try:
        with fsspec.open(url, "rb") as f:
            return bytes(f.read())
    except OSError as e:
        raise OSError(f"{url}: cannot open: {e}") from e
