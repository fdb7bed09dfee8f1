-- Structured LLM output for the translation graph: a JSON schema built from
-- the command registry (squawk.sim.commands()), sent with the request
-- (Ollama `format`, OpenAI `response_format`), so a server that honours it
-- can only answer with known command names and argument counts.
--
-- The reply shape: {"commands": [{"name": "ALT", "args": ["KL204", "FL300"]}, ...],
--                   "ask": ""}   ("ask" non-empty: a question instead)
-- Argument counts come from each command's argument spec: `latlon` is two
-- tokens, `[...]` parts are optional, `...` and a trailing `string` take the
-- rest of the line; `onoff` is ON or OFF.
--
-- API:
--   for_commands([names]) -> schema table (all registry commands, or those named)
--   read(reply) -> line, ask   the TrafScript line ("CMD a b ; CMD c") or the
--       question of a reply in that shape; nil, nil when the reply is not
--       JSON of that shape (the caller falls back to reading free text)
local M = {}

-- min and max token counts of an argument spec ("acid,alt,[vspd]" -> 2, 3);
-- max is nil when the rest of the line is taken.
local function counts(spec)
  local min, max, optional = 0, 0, false
  for part in (spec or ""):gmatch("[^,]+") do
    local open = part:find("%[")
    if open then optional = true end
    local name = part:gsub("[%[%]%s]", "")
    local n = name:find("latlon", 1, true) and 2 or 1
    if name == "..." or name == "string" then
      max = nil
      if not optional then min = min + 1 end
    else
      if max then max = max + n end
      if not optional then min = min + n end
    end
    if part:find("%]") then optional = false end
  end
  return min, max
end
M.counts = counts

local function command_schema(c)
  local min, max = counts(c.args)
  local args = { type = "array", items = { type = "string" }, minItems = min,
                 description = c.usage }
  if max then args.maxItems = max end
  return {
    type = "object",
    properties = { name = { type = "string", enum = { c.name } }, args = args },
    required = { "name", "args" },
    additionalProperties = false,
  }
end

function M.for_commands(names)
  local wanted
  if names then
    wanted = {}
    for _, n in ipairs(names) do wanted[n:upper()] = true end
  end
  local choices = {}
  for _, c in ipairs(squawk.sim.commands()) do
    if not wanted or wanted[c.name:upper()] then choices[#choices + 1] = command_schema(c) end
  end
  return {
    type = "object",
    properties = {
      commands = { type = "array", items = { anyOf = choices } },
      ask = { type = "string", description = "a question when required information is missing, else empty" },
    },
    required = { "commands", "ask" },
    additionalProperties = false,
  }
end

function M.read(reply)
  local ok, v = pcall(squawk.translate.json_decode, reply)
  if not ok or type(v) ~= "table" or type(v.commands) ~= "table" then return nil, nil end
  if type(v.ask) == "string" and v.ask:match("%S") then return nil, v.ask end
  local lines = {}
  for _, c in ipairs(v.commands) do
    if type(c) ~= "table" or type(c.name) ~= "string" then return nil, nil end
    local words = { c.name }
    for _, a in ipairs(type(c.args) == "table" and c.args or {}) do words[#words + 1] = tostring(a) end
    lines[#lines + 1] = table.concat(words, " ")
  end
  if #lines == 0 then return nil, nil end
  return table.concat(lines, " ; "), nil
end

return M
