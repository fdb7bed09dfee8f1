-- LLM client options are validated (issue 12 points 11, 12, 18).
local function refused(opts, needle)
  local ok, err = pcall(squawk.llm.client, opts)
  check(not ok, "refused: " .. needle)
  check(tostring(err):find(needle, 1, true) ~= nil, tostring(err))
end
local base = "http://127.0.0.1:1"
refused({ url = base, model = "m", timeout = 0 / 0 }, "timeout")
refused({ url = base, model = "m", timeout = 1e-9 }, "timeout")
refused({ url = base, model = "m", timeout = math.huge }, "timeout")
refused({ url = base, model = "m", connect_timeout = -1 }, "timeout")
refused({ url = base, model = "m", context = 4294967297 }, "field 'context'")
refused({ url = base, model = "m", max_tokens = 0 / 0 }, "field 'max_tokens'")
refused({ url = base, model = "m", max_reply_bytes = 0 }, "field 'max_reply_bytes'")
check(squawk.llm.client({ url = base, model = "m", timeout = 0.5, max_reply_bytes = 4096 }))
