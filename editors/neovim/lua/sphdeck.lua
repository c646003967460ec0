-- sphdeck for Neovim's built-in LSP client (no plugin needed): filetypes for LS-DYNA and OpenRadioss
-- decks, and `sphdeck lsp` started for their buffers, one server per project root.
--   require("sphdeck").setup({ cmd = { "/path/to/sphdeck", "lsp" } })
-- Works on Neovim 0.7 (Debian 12: vim.lsp.start_client + vim.lsp.buf_attach_client) and 0.8 or later
-- (vim.lsp.start, vim.filetype.add).
local M = {}

M.filetypes = { "lsdyna", "openradioss" }

-- A deck's dialect from its first significant lines: LS-DYNA keywords start with '*', OpenRadioss
-- ones with '/' (or the '#RADIOSS STARTER' header). '$' comments LS-DYNA lines, '#' Radioss ones.
function M.dialect_of_lines(lines)
  for _, line in ipairs(lines) do
    if line:match("^#RADIOSS") or line:match("^/%u") then
      return "openradioss"
    elseif line:match("^%*%a") then
      return "lsdyna"
    end
  end
  return nil
end

local function first_lines(bufnr, count)
  return vim.api.nvim_buf_get_lines(bufnr, 0, count, false)
end

-- The folder holding sphdeck.toml or .git above `path`, or the file's own folder.
function M.root_dir(path)
  local dir = vim.fn.fnamemodify(path, ":p:h")
  local toml = vim.fn.findfile("sphdeck.toml", dir .. ";")
  if toml ~= "" then
    return vim.fn.fnamemodify(toml, ":p:h")
  end
  local git = vim.fn.finddir(".git", dir .. ";")
  if git ~= "" then
    return vim.fn.fnamemodify(git, ":p:h:h")
  end
  return dir
end

local function detect_filetypes()
  if vim.fn.has("nvim-0.8") == 1 then
    vim.filetype.add({
      extension = {
        k = "lsdyna",
        key = "lsdyna",
        dyn = "lsdyna",
        rad = "openradioss",
        -- both dialects use .inc: tell them apart by content, else Neovim's own guess
        inc = function(_, bufnr)
          return M.dialect_of_lines(first_lines(bufnr, 200))
        end,
      },
      pattern = { [".*_%d%d%d%d%.rad"] = "openradioss" },
    })
    return
  end
  -- Neovim 0.7: filetype.vim's own rules (*.k kwt, *.rad radiance) use :setf, so `set filetype`
  -- here wins whichever autocommand runs first.
  local group = vim.api.nvim_create_augroup("sphdeck_filetypes", { clear = true })
  vim.api.nvim_create_autocmd({ "BufRead", "BufNewFile" }, {
    group = group,
    pattern = { "*.k", "*.key", "*.dyn" },
    command = "set filetype=lsdyna",
  })
  vim.api.nvim_create_autocmd({ "BufRead", "BufNewFile" }, {
    group = group,
    pattern = { "*.rad" },
    command = "set filetype=openradioss",
  })
  vim.api.nvim_create_autocmd({ "BufRead" }, {
    group = group,
    pattern = { "*.inc" },
    callback = function(args)
      local dialect = M.dialect_of_lines(first_lines(args.buf, 200))
      if dialect then
        vim.bo[args.buf].filetype = dialect
      end
    end,
  })
end

-- Neovim 0.7 has no vim.lsp.start: one client per root, reused while it runs.
local clients_by_root = {}

local function attach_07(bufnr, config)
  local id = clients_by_root[config.root_dir]
  local client = id and vim.lsp.get_client_by_id(id)
  if not client or client.is_stopped() then
    id = vim.lsp.start_client(config)
    if not id then
      vim.notify("sphdeck: could not start " .. table.concat(config.cmd, " "), vim.log.levels.ERROR)
      return nil
    end
    clients_by_root[config.root_dir] = id
  end
  vim.lsp.buf_attach_client(bufnr, id)
  return id
end

-- Starts (or reuses) the server for buffer `bufnr` and attaches it; returns the client id.
function M.attach(bufnr, opts)
  opts = opts or M.options or {}
  local path = vim.api.nvim_buf_get_name(bufnr)
  local config = {
    name = "sphdeck",
    cmd = opts.cmd or { "sphdeck", "lsp" },
    root_dir = M.root_dir(path ~= "" and path or vim.fn.getcwd() .. "/x"),
    flags = { debounce_text_changes = opts.debounce_ms or 50 },
    on_attach = function(client, attached)
      -- completion with <C-x><C-o> (Neovim 0.7 does not set it by itself)
      vim.bo[attached].omnifunc = "v:lua.vim.lsp.omnifunc"
      -- field names beside values (Neovim 0.10+); `inlay_hints = false` leaves them off
      if opts.inlay_hints ~= false and vim.lsp.inlay_hint and vim.lsp.inlay_hint.enable then
        pcall(vim.lsp.inlay_hint.enable, true, { bufnr = attached })
      end
      if opts.on_attach then
        opts.on_attach(client, attached)
      end
    end,
    on_exit = opts.on_exit,
    capabilities = opts.capabilities,
    settings = opts.settings,
    -- {inlayHints = {bulkBlocks = true}} shows hints in *NODE / *ELEMENT_SPH blocks too
    init_options = opts.init_options,
  }
  if vim.lsp.start then
    return vim.lsp.start(config, { bufnr = bufnr })
  end
  return attach_07(bufnr, config)
end

-- Colours for what the server's semantic tokens add to Neovim's defaults (0.9+ links the standard
-- types such as @lsp.type.keyword itself): sphdeck's own type `real`, and the modifiers. `default`:
-- a colour scheme or the user's own setting wins.
function M.default_highlights()
  if vim.fn.has("nvim-0.9") == 0 then
    return -- no semantic tokens before 0.9 (and 0.7 refuses '@' in group names)
  end
  local function set(group, spec)
    spec.default = true
    pcall(vim.api.nvim_set_hl, 0, group, spec)
  end
  set("@lsp.type.real", { link = "Float" })
  set("@lsp.type.enumMember", { link = "Constant" })
  set("@lsp.mod.header", { link = "SpecialComment" })
  set("@lsp.mod.include", { link = "Include" })
  set("@lsp.mod.oddField", { italic = true }) -- every other field of a card: a value in the wrong columns shows
end

function M.setup(opts)
  M.options = opts or {}
  detect_filetypes()
  M.default_highlights()
  vim.api.nvim_create_autocmd("FileType", {
    group = vim.api.nvim_create_augroup("sphdeck_lsp", { clear = true }),
    pattern = M.filetypes,
    callback = function(args)
      M.attach(args.buf)
    end,
  })
end

return M
