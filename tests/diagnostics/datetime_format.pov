// error: 5:32 `%Z` cannot be used
// error-text: in this datetime

// datetime() with a format naming a time zone.
#declare Stamp = datetime(now, "%Y %Z");
