-- The editor test of issue 16: Debian's Neovim, headless, with editors/neovim/lua/sphdeck.lua, talks
-- to `sphdeck lsp`: open a deck with a known finding, wait for its diagnostic, hover a field, ask
-- for semantic tokens and inlay hints (issue 29), fix the
-- finding with an edit, wait for the diagnostic to go; then on a deck with an include (issue 45):
-- document links, workspace symbols, code lens and a rename across the include; shut the server down.
--   SPHDECK=build/sphdeck nvim --headless --clean -u tests/editor/neovim_lsp_test.lua
-- (tests/editor/run_neovim_test.sh sets it up.) Exit 0 on success; otherwise a printed reason and
-- exit 1 (a check failed) or 3 (the global time limit passed). Every wait is bounded.
local source_dir = vim.fn.fnamemodify(debug.getinfo(1, "S").source:sub(2), ":p:h:h:h")
local sphdeck = os.getenv("SPHDECK") or (source_dir .. "/build/sphdeck")
local deck = source_dir .. "/tests/editor/bad_endcyc.k"
local time_limit_ms = tonumber(os.getenv("SPHDECK_EDITOR_TIMEOUT_MS") or "20000")
local started = vim.loop.now()

local function say(text)
  io.stdout:write("editor-neovim: " .. text .. "\n")
  io.stdout:flush()
end

local function fail(reason, code)
  io.stderr:write("editor-neovim: FAILED: " .. reason .. "\n")
  io.stderr:flush()
  -- leave no server behind: a forced stop kills it (client ids count from 1; get_active_clients
  -- misses a client still initializing)
  for id = 1, 8 do
    pcall(vim.lsp.stop_client, id, true)
  end
  os.exit(code or 1)
end

-- The waits below share the global limit and say what they waited for; this timer, 2 s later, ends
-- the run should something block outside them (vim.wait runs timers).
local watchdog = vim.loop.new_timer()
watchdog:start(time_limit_ms + 2000, 0, function()
  fail(("no result within %d ms (global time limit)"):format(time_limit_ms + 2000), 3)
end)

local function remaining_ms()
  return math.max(0, time_limit_ms - (vim.loop.now() - started))
end

local server_exit = nil -- {code, signal} once the server process ended

-- vim.wait bounded by the global limit; fails with `what` when `condition` never holds, and at once
-- when the server ends before (unless its end is what is awaited).
local function wait_for(what, condition, server_may_end)
  local ended_early = false
  local done = vim.wait(remaining_ms(), function()
    if condition() then
      return true
    end
    ended_early = server_exit ~= nil and not server_may_end
    return ended_early
  end, 20)
  if ended_early then
    fail(("the server ended (exit code %s, signal %s) while waiting for %s"):format(
      server_exit.code, server_exit.signal, what))
  elseif not done then
    fail("timed out waiting for " .. what)
  end
end

if vim.fn.executable(sphdeck) ~= 1 then
  fail("sphdeck executable not found: " .. sphdeck .. " (set SPHDECK)")
end
vim.opt.swapfile = false
vim.opt.shadafile = "NONE"

package.path = source_dir .. "/editors/neovim/lua/?.lua;" .. package.path
local sphdeck_nvim = require("sphdeck")
sphdeck_nvim.setup({
  cmd = { sphdeck, "lsp" },
  on_exit = function(code, signal)
    server_exit = { code = code, signal = signal }
  end,
})
-- Server messages on stderr would be useful when the test fails.
vim.lsp.set_log_level("WARN")

vim.cmd("edit " .. vim.fn.fnameescape(deck))
local buf = vim.api.nvim_get_current_buf()
if vim.bo[buf].filetype ~= "lsdyna" then
  fail("filetype of " .. deck .. " is '" .. vim.bo[buf].filetype .. "', expected lsdyna")
end
say("nvim " .. tostring(vim.version().major) .. "." .. tostring(vim.version().minor) .. "." ..
    tostring(vim.version().patch) .. ", server " .. sphdeck)

local client_id = nil
wait_for("the server to start and answer initialize", function()
  -- vim.lsp.get_clients from 0.10 on, vim.lsp.buf_get_clients before
  local clients = vim.lsp.get_clients and vim.lsp.get_clients({ bufnr = buf }) or vim.lsp.buf_get_clients(buf)
  for _, client in pairs(clients) do
    if client.name == "sphdeck" then
      client_id = client.id
      return true
    end
  end
  return false
end)
wait_for("the server to initialize", function()
  local client = vim.lsp.get_client_by_id(client_id)
  return client ~= nil and client.server_capabilities ~= nil and next(client.server_capabilities) ~= nil
end)
say("attached, client " .. client_id)

-- 1. The finding of the deck: DK002 at line 6, column 15 (0-based 5, 14), an error.
local function dk002()
  for _, d in ipairs(vim.diagnostic.get(buf)) do
    if d.code == "DK002" or (d.user_data and d.user_data.lsp and d.user_data.lsp.code == "DK002") then
      return d
    end
  end
  return nil
end
wait_for("the DK002 diagnostic", function() return dk002() ~= nil end)
local d = dk002()
if d.lnum ~= 5 or d.col ~= 14 then
  fail(("DK002 at line %d col %d (0-based), expected 5, 14"):format(d.lnum, d.col))
end
if d.severity ~= vim.diagnostic.severity.ERROR then
  fail("DK002 severity " .. tostring(d.severity) .. ", expected ERROR")
end
if not d.message:find("10000O", 1, true) then
  fail("DK002 message does not quote the value: " .. d.message)
end
say("diagnostic: " .. d.message)

-- 2. Hover on the ENDTIM value (line 6, column 8).
local params = {
  textDocument = { uri = vim.uri_from_bufnr(buf) },
  position = { line = 5, character = 7 },
}
local responses, err = vim.lsp.buf_request_sync(buf, "textDocument/hover", params, math.min(5000, remaining_ms()))
if not responses then
  fail("no hover answer: " .. tostring(err))
end
local response = responses[client_id]
if not response or response.error or not response.result then
  fail("hover answered " .. vim.inspect(response))
end
local text = table.concat(vim.lsp.util.convert_input_to_markdown_lines(response.result.contents), "\n")
if not text:upper():find("ENDTIM", 1, true) then
  fail("hover on ENDTIM does not name the field:\n" .. text)
end
if not text:find("0.002", 1, true) then
  fail("hover on ENDTIM does not give its value 0.002:\n" .. text)
end
say("hover: " .. text:gsub("\n", " | "))

-- 2b. Semantic tokens and inlay hints (issue 29), asked for directly: Neovim 0.9+ asks for the tokens
-- by itself, Debian's 0.7 does not, so the test sends the requests and reads the answers.
local function ask(method, request_params)
  local answers, ask_err = vim.lsp.buf_request_sync(buf, method, request_params, math.min(5000, remaining_ms()))
  if not answers then
    fail("no answer to " .. method .. ": " .. tostring(ask_err))
  end
  local answer = answers[client_id]
  if not answer or answer.error or not answer.result then
    fail(method .. " answered " .. vim.inspect(answer))
  end
  return answer.result
end
local provider = vim.lsp.get_client_by_id(client_id).server_capabilities.semanticTokensProvider
if not provider or not provider.legend then
  fail("the server announces no semantic tokens legend")
end
local legend = provider.legend
local tokens = ask("textDocument/semanticTokens/full", { textDocument = params.textDocument }).data
local decoded, line, start = {}, 0, 0
for i = 1, #tokens, 5 do
  if tokens[i] ~= 0 then start = 0 end
  line = line + tokens[i]
  start = start + tokens[i + 1]
  local mods = {}
  for bit, name in ipairs(legend.tokenModifiers) do
    if math.floor(tokens[i + 4] / 2 ^ (bit - 1)) % 2 == 1 then mods[name] = true end
  end
  table.insert(decoded, { line = line, start = start, length = tokens[i + 2],
                          type = legend.tokenTypes[tokens[i + 3] + 1], mods = mods })
end
local function token_at(l, c)
  for _, t in ipairs(decoded) do
    if t.line == l and c >= t.start and c < t.start + t.length then return t end
  end
  return nil
end
local expected_tokens = {
  { 3, 1, "keyword" },  -- *CONTROL_TERMINATION
  { 4, 3, "comment", "header" },  -- the $# line
  { 5, 7, "real" },  -- ENDTIM 0.002
  { 5, 15, "number", "oddField" },  -- ENDCYC 10000O (unreadable, still an integer field), the second field
}
for _, e in ipairs(expected_tokens) do
  local t = token_at(e[1], e[2])
  if not t or t.type ~= e[3] or (e[4] and not t.mods[e[4]]) then
    fail(("semantic token at %d:%d is %s, expected %s %s"):format(e[1], e[2], vim.inspect(t), e[3], e[4] or ""))
  end
end
say(("semantic tokens: %d, keyword, header comment, real and odd-field number where expected"):format(#decoded))
local hints = ask("textDocument/inlayHint", {
  textDocument = params.textDocument,
  range = { start = { line = 0, character = 0 }, ["end"] = { line = 6, character = 0 } },
})
local labels = {}
for _, h in ipairs(hints) do
  local label = type(h.label) == "string" and h.label or h.label[1].value
  labels[h.position.line .. ":" .. label] = true
end
if not labels["5:ENDTIM:"] or not labels["5:ENDCYC:"] then
  fail("inlay hints do not name ENDTIM and ENDCYC on line 6: " .. vim.inspect(hints))
end
say(("inlay hints: %d, ENDTIM and ENDCYC named"):format(#hints))

-- 3. Fix ENDCYC (a zero, not the letter O): Neovim sends didChange; the diagnostic must go.
vim.api.nvim_buf_set_lines(buf, 5, 6, false, { "     0.002     10000" })
wait_for("the DK002 diagnostic to go after the fix", function() return dk002() == nil end)
say("diagnostic gone after the edit")

-- 3b. Issue 45: a deck with an include (tests/editor/rename_main.k): document links, workspace symbols,
-- code lens, and a rename across the include applied as Neovim applies it (the buffers change, nothing
-- is saved); a new id too wide for its field is refused with the reason.
local main_deck = source_dir .. "/tests/editor/rename_main.k"
local section_deck = source_dir .. "/tests/editor/rename_section.k"
vim.cmd("edit " .. vim.fn.fnameescape(main_deck))
local main_buf = vim.api.nvim_get_current_buf()
wait_for("the server to attach to rename_main.k", function()
  local clients = vim.lsp.get_clients and vim.lsp.get_clients({ bufnr = main_buf }) or vim.lsp.buf_get_clients(main_buf)
  for _, client in pairs(clients) do
    if client.id == client_id then return true end
  end
  return false
end)
local function ask_main(method, request_params)
  local answers, ask_err = vim.lsp.buf_request_sync(main_buf, method, request_params, math.min(5000, remaining_ms()))
  if not answers or not answers[client_id] then
    fail("no answer to " .. method .. ": " .. tostring(ask_err))
  end
  return answers[client_id]
end
local main_document = { uri = vim.uri_from_bufnr(main_buf) }
local links = ask_main("textDocument/documentLink", { textDocument = main_document }).result
if not links or #links ~= 1 or links[1].target ~= vim.uri_from_fname(section_deck) or links[1].range.start.line ~= 4 then
  fail("document links of rename_main.k: " .. vim.inspect(links))
end
say("document link: " .. links[1].target)
local symbols = ask_main("workspace/symbol", { query = "sect" }).result or {}
local found_section = false
for _, s in ipairs(symbols) do
  if s.name == "SECTION 3" and s.location.uri == vim.uri_from_fname(section_deck) then found_section = true end
end
if not found_section then
  fail("workspace symbols for 'sect' do not list SECTION 3 of the include: " .. vim.inspect(symbols))
end
say(("workspace symbols: %d for 'sect'"):format(#symbols))
local lenses = ask_main("textDocument/codeLens", { textDocument = main_document }).result or {}
local lens_titles = {}
for _, l in ipairs(lenses) do table.insert(lens_titles, l.command and l.command.title or "?") end
if #lenses ~= 2 or lens_titles[1] ~= "used by 0" or lens_titles[2] ~= "used by 1" then
  fail("code lenses of rename_main.k (PART 1, MAT 5): " .. vim.inspect(lens_titles))
end
say("code lens: " .. table.concat(lens_titles, ", "))
local secid = { textDocument = main_document, position = { line = 8, character = 19 } }
local refused = ask_main("textDocument/rename", vim.tbl_extend("force", secid, { newName = "12345678901" }))
if not refused.error or not refused.error.message:find("does not fit the 10-column field SECID", 1, true) then
  fail("a too wide id was not refused with its reason: " .. vim.inspect(refused))
end
say("rename refused: " .. refused.error.message)
local renamed = ask_main("textDocument/rename", vim.tbl_extend("force", secid, { newName = "42" }))
if renamed.error or not renamed.result then
  fail("rename answered " .. vim.inspect(renamed))
end
vim.lsp.util.apply_workspace_edit(renamed.result, "utf-16")
local section_buf = vim.fn.bufnr(section_deck)
local part_line = vim.api.nvim_buf_get_lines(main_buf, 8, 9, false)[1]
local section_line = section_buf > 0 and vim.api.nvim_buf_get_lines(section_buf, 3, 4, false)[1] or nil
if part_line ~= "         1        42         5" or section_line ~= "        42       1.2" then
  fail(("rename across the include gave %q and %q"):format(tostring(part_line), tostring(section_line)))
end
say("renamed section 3 to 42 in rename_main.k and its include")

-- 4. Shutdown and exit: the server must end by itself with exit code 0.
vim.lsp.stop_client(client_id)
wait_for("the server to exit after shutdown", function() return server_exit ~= nil end, true)
if server_exit.code ~= 0 or server_exit.signal ~= 0 then
  fail(("server ended with code %s, signal %s after shutdown"):format(server_exit.code, server_exit.signal))
end
say(("passed in %d ms"):format(vim.loop.now() - started))
watchdog:stop()
os.exit(0)
