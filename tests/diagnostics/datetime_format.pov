// datetime() with a format naming a time zone.
#declare Stamp = datetime(now, "%Y %Z");
