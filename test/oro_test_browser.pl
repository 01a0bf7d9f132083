:- module(oro_test_browser,
          [ browser_available/0,
            browser_start/1,            % -Browser
            browser_stop/1,             % +Browser
            browser_open/3,             % +Browser, +URL, -Ready
            browser_eval/3,             % +Browser, +Expression, -Value
            browser_errors/2,           % +Browser, -Errors
            browser_screenshot/3,       % +Browser, +File, -Distinct
            png_distinct_bytes/2        % +File, -Distinct
          ]).
:- use_module(library(process)).
:- use_module(library(http/websocket)).
:- use_module(library(http/http_open)).
:- use_module(library(http/json)).
:- use_module(library(readutil)).
:- use_module(library(filesex)).
:- use_module(library(base64)).
:- use_module(library(zlib)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(error)).
:- use_module(oro_test_support, [test_wait_until/2, test_process_wait/3]).

/** <module> A headless Chromium for the tests, driven over DevTools

Debian's `chromium`, started headless on a temporary profile with its
DevTools endpoint on a free port (`--remote-debugging-port=0`: the
browser writes the port it took into `DevToolsActivePort` in the
profile), is driven over the DevTools protocol by a websocket
(library(http/websocket)): open a page, evaluate JavaScript in it,
collect the console errors and uncaught exceptions, take a
screenshot.  browser_stop/1 closes it, kills it by its PID if need be,
and removes the profile.
*/

:- dynamic
    event/3,                            % Browser, Method, Params
    next_id/2.                          % Browser, Id

%!  browser_available is semidet.
%
%   Debian's chromium is installed.

browser_available :-
    absolute_file_name(path(chromium), _,
                       [access(execute), file_errors(fail)]).

%!  browser_start(-Browser) is det.
%
%   Start a headless Chromium and connect to its first page.

browser_start(browser(Pid, Dir, WS)) :-
    tmp_file(oro_chromium, Dir),
    make_directory(Dir),
    atom_concat('--user-data-dir=', Dir, DirOption),
    process_create(path(chromium),
                   [ '--headless', '--no-sandbox', '--disable-gpu',
                     '--no-first-run', '--no-default-browser-check',
                     '--disable-extensions', '--mute-audio',
                     '--remote-debugging-port=0',
                     '--remote-allow-origins=*',
                     '--window-size=1280,900',
                     DirOption, 'about:blank'
                   ],
                   [ process(Pid), stdin(null), stdout(null), stderr(null) ]),
    directory_file_path(Dir, 'DevToolsActivePort', PortFile),
    (   test_wait_until(port_file_ready(PortFile), 60)
    ->  true
    ;   browser_kill(Pid, Dir),
        throw(error(timeout_error(chromium, start), _))
    ),
    read_file_to_string(PortFile, Text, []),
    split_string(Text, "\n", " \r", [PortText|_]),
    number_string(Port, PortText),
    (   test_wait_until(page_target(Port, _), 30),
        page_target(Port, WsURL)
    ->  true
    ;   browser_kill(Pid, Dir),
        throw(error(existence_error(chromium_page, Port), _))
    ),
    http_open_websocket(WsURL, WS, []),
    set_stream(WS, timeout(60)),
    Browser = browser(Pid, Dir, WS),
    retractall(next_id(Browser, _)),
    assertz(next_id(Browser, 1)),
    cdp(Browser, 'Runtime.enable', _{}, _),
    cdp(Browser, 'Log.enable', _{}, _),
    cdp(Browser, 'Page.enable', _{}, _).

port_file_ready(File) :-
    exists_file(File),
    read_file_to_string(File, Text, []),
    sub_string(Text, _, _, _, "\n").

page_target(Port, WsURL) :-
    format(atom(URL), 'http://127.0.0.1:~w/json/list', [Port]),
    catch(setup_call_cleanup(
              http_open(URL, In, [timeout(10)]),
              json_read_dict(In, Targets, [value_string_as(atom)]),
              close(In)),
          _, fail),
    member(T, Targets),
    T.type == page,
    WsURL = T.webSocketDebuggerUrl,
    !.

%!  browser_stop(+Browser) is det.
%
%   Close the browser, wait for its process (killing it by PID after
%   10 seconds) and remove its profile.

browser_stop(Browser) :-
    Browser = browser(Pid, Dir, WS),
    catch(cdp(Browser, 'Browser.close', _{}, _), _, true),
    catch(ws_close(WS, 1000, ""), _, true),
    browser_kill(Pid, Dir),
    retractall(event(Browser, _, _)),
    retractall(next_id(Browser, _)).

browser_kill(Pid, Dir) :-
    test_process_wait(Pid, Status, 10),
    (   Status \== timeout
    ->  true
    ;   catch(process_kill(Pid, kill), _, true),
        process_wait(Pid, _)
    ),
    catch(delete_directory_and_contents(Dir), _, true).

%!  browser_open(+Browser, +URL, -Ready) is det.
%
%   Load URL, clear the errors seen so far and wait (30 s at most)
%   until its script has drawn the page: Ready is the page's
%   `data-ready` (`true`, `error`), or `timeout`.

browser_open(Browser, URL, Ready) :-
    retractall(event(Browser, _, _)),
    cdp(Browser, 'Page.navigate', _{url:URL}, _),
    (   test_wait_until(page_ready(Browser, Ready0), 30)
    ->  Ready = Ready0
    ;   Ready = timeout
    ).

page_ready(Browser, Ready) :-
    browser_eval(Browser,
                 "document.readyState === 'complete' && document.body ? \c
                  (document.body.dataset.ready || '') : ''", Value),
    Value \== "",
    atom_string(Ready, Value).

%!  browser_eval(+Browser, +Expression, -Value) is det.
%
%   Value is the value of the JavaScript Expression in the page (a
%   JSON value: string, number, boolean, null).

browser_eval(Browser, Expression, Value) :-
    cdp(Browser, 'Runtime.evaluate',
        _{expression:Expression, returnByValue:true}, Result),
    (   get_dict(result, Result, R),
        get_dict(value, R, Value0)
    ->  Value = Value0
    ;   Value = null
    ).

%!  browser_errors(+Browser, -Errors) is det.
%
%   Errors are the console errors, uncaught exceptions and errors the
%   browser logged (a resource that failed to load, ...) since the
%   page was opened, as strings.

browser_errors(Browser, Errors) :-
    findall(E, ( event(Browser, Method, Params),
                 error_event(Method, Params, E)
               ), Errors).

error_event('Runtime.consoleAPICalled', P, Text) :-
    P.type == "error",
    format(string(Text), 'console.error: ~q', [P.args]).
error_event('Runtime.exceptionThrown', P, Text) :-
    format(string(Text), 'exception: ~q', [P.exceptionDetails]).
error_event('Log.entryAdded', P, Text) :-
    P.entry.level == "error",
    format(string(Text), 'log: ~w ~w', [P.entry.text, P.entry.get(url, '')]).

%!  browser_screenshot(+Browser, +File, -Distinct) is det.
%
%   Save a PNG screenshot of the page to File; Distinct is the number
%   of distinct byte values of its decompressed image data (see
%   png_distinct_bytes/2): a blank page has a handful.

browser_screenshot(Browser, File, Distinct) :-
    cdp(Browser, 'Page.captureScreenshot', _{format:png}, Result),
    atom_string(Base64, Result.data),
    base64(Bytes, Base64),
    setup_call_cleanup(open(File, write, Out, [type(binary)]),
                       write(Out, Bytes),
                       close(Out)),
    png_distinct_bytes(File, Distinct).

%!  png_distinct_bytes(+File, -Distinct) is det.
%
%   Distinct is the number of distinct byte values in the inflated
%   IDAT data of the PNG File.

png_distinct_bytes(File, Distinct) :-
    read_file_to_codes(File, Codes, [type(binary)]),
    Codes = [0x89, 0'P, 0'N, 0'G, _, _, _, _|Chunks],
    idat(Chunks, Idat),
    tmp_file(oro_png, Tmp),
    setup_call_cleanup(open(Tmp, write, Out, [type(binary)]),
                       maplist(put_byte(Out), Idat),
                       close(Out)),
    setup_call_cleanup(
        ( open(Tmp, read, In0, [type(binary)]),
          zopen(In0, In, [format(deflate)])
        ),
        read_stream_to_codes(In, Raw),
        ( close(In),
          delete_file(Tmp)
        )),
    sort(Raw, Values),
    length(Values, Distinct).

idat([], []).
idat([L1, L2, L3, L4, T1, T2, T3, T4|Rest], Data) :-
    Len is (L1 << 24) \/ (L2 << 16) \/ (L3 << 8) \/ L4,
    length(Body, Len),
    append(Body, [_, _, _, _|Next], Rest),
    (   [T1, T2, T3, T4] == `IDAT`
    ->  append(Body, Data1, Data)
    ;   Data = Data1
    ),
    (   [T1, T2, T3, T4] == `IEND`
    ->  Data1 = []
    ;   idat(Next, Data1)
    ).

		 /*******************************
		 *        DEVTOOLS CALLS        *
		 *******************************/

%   cdp(+Browser, +Method, +Params, -Result): one DevTools call; the
%   events read meanwhile are kept for browser_errors/2.

cdp(Browser, Method, Params, Result) :-
    Browser = browser(_, _, WS),
    retract(next_id(Browser, Id)),
    Id1 is Id + 1,
    assertz(next_id(Browser, Id1)),
    ws_send(WS, json(_{id:Id, method:Method, params:Params})),
    cdp_reply(Browser, WS, Id, Result).

cdp_reply(Browser, WS, Id, Result) :-
    ws_receive(WS, Message, [format(json), value_string_as(string)]),
    (   Message.opcode == close
    ->  throw(error(existence_error(chromium, connection), _))
    ;   true
    ),
    Data = Message.data,
    (   get_dict(id, Data, Id)
    ->  (   get_dict(error, Data, Error)
        ->  throw(error(chromium_error(Error), _))
        ;   Result = Data.result
        )
    ;   get_dict(method, Data, Method)
    ->  atom_string(MethodA, Method),
        assertz(event(Browser, MethodA, Data.params)),
        cdp_reply(Browser, WS, Id, Result)
    ;   cdp_reply(Browser, WS, Id, Result)
    ).
