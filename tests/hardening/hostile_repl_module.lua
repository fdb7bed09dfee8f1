-- Issue 52 point 2: a translate.repl module (dropped into a home's
-- scripts/translate/repl.lua) whose every field read raises a table: the
-- REPL must report it and fall back to TrafScript only, never panic.
return setmetatable({}, {__index = function() error({}) end})
