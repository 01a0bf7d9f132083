/*  The examples of README.md, run as written.

    Every code block of README.md (indented by 4 spaces after a blank
    line, or fenced with ```) is either an example, run by a test named
    after the line of its marker, or listed by readme_not_example/2
    below (synopses, sample output, the Setup commands the suite
    itself embodies).  test(every_block_is_run_or_listed) fails on any
    other block, so a new example cannot go untested.  An example is
    marked by a comment on the nearest non-blank line before its block
    (before the opening ``` of a fenced one):

        <!-- readme-test: KIND [ARG ...] -->

    Commands and code are run as written, but for ports: the servers
    the tests start listen on free ports, and the README's fixed ports
    6969 (ORO), 6970 (HTTP) and 6971 (KB-API) are rewritten to those
    in everything run (a server command without a port gets
    `--port=0`, and `--http=0` unless it names one).

    - telnet [SERVER OPTION ...]: the real server (swipl
      server/oro_server.pl, in the checkout) with the options of the
      marker; the block's requests (up to each `#end#`) are sent on one
      connection and each reply (up to its `#end#`; the line after a
      `close`) must be the block's lines.  Lines starting with `$ `
      are commands, skipped.
    - prolog: a toplevel session: `swipl -p library=prolog` in the
      checkout, each `?- Goal.` run in turn by
      test/fixtures/readme_toplevel.pl; the lines under a goal must be
      how its output and answers begin (a line ` ;`-terminated asks
      for one more answer; `...` stops the comparison).  A goal shown
      without lines must succeed.
    - prolog-client [SERVER OPTION ...]: the same, with a server
      running (another process), as a client of it would do.
    - shell [SERVER OPTION ...]: each `$ COMMAND` line (continued by a
      trailing `\`) is run by `sh -c` in the checkout, with a server
      started with the options of the marker (a `$ ... &` line, the
      server started in the background, stands for it and is not run);
      the command must exit with status 0 and its output (carriage
      returns dropped) begin with the lines under it (`...` stops the
      comparison).
    - serve [METHOD ...]: the block is a command that starts a server,
      run from a temporary directory (its script and its --ontology
      and --plugin files taken from the checkout, the options kept in
      their order; a `swipl -g ...` command gets
      `-p library=CHECKOUT/prolog`, standing for the installed pack):
      it must print its listening line, and `listSimpleMethods` must
      list each METHOD.
    - config: a settings file (named by its first line, `% FILE`), a
      blank line, then the command that uses it, run in a temporary
      directory (`--log=PATH` there too; `setting(port, N)` rewritten
      to port 0): the server must listen on the port the file sets
      (not 6969) and log a request.
    - log-format: sample lines of the request log: a server with
      `--log` answers a request of each line's method (the requests
      are readme_log_request/2) and each real line must have the
      sample's fields (time format, keys, method, peer, outcome).
    - python: the block is written to a file and run by
      test/fixtures/readme_python.py with python3 (clients/python on
      PYTHONPATH, ORO_HOST and ORO_PORT naming the server): its output
      must be the comments of its expression and `+=` statements, in
      order (other comments are remarks).  Skipped with a notice
      without python3.
    - plugin METHOD CLASS: the block is written to a file, a server
      started with `--plugin=FILE` as its first option, and METHOD
      CLASS must answer the number of instances getInstancesOf CLASS
      lists.
    - nodes-start: commands that start servers in the background
      (`CMD &`), run by the test of the `nodes` block that follows.
    - nodes LINE ...: a shell script run by bash in the checkout after
      the commands of the `nodes-start` block before it, its ports
      (6380 for Redis, 7001 and 7002 for the nodes) rewritten to free
      ones; the test waits (bounded) until both nodes listen and runs
      the block's last command again (bounded) until its output holds
      `cup1` (replication takes a moment): that output must be the
      marker's LINEs.  Skipped with a notice without redis-server.
    - pack: each `?- Goal.` (a pack_install/2 of `file:///path/to/oro`)
      is run with the checkout for /path/to/oro and HOME and
      XDG_DATA_HOME in a temporary directory, as a user would; then
      library(oro) must load and answer from another directory.

    When merging a branch that adds README blocks: mark each example
    with one of the kinds above (or add a kind), and add each block
    that is no example (a synopsis, sample output) as a
    readme_not_example(FirstLine, Why) fact, FirstLine being the text
    of its first line without the indent; then run
    `swipl test/run_tests.pl test_readme`.
*/

:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(process)).
:- use_module(library(readutil)).
:- use_module(library(socket)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(aggregate)).
:- use_module(library(pairs)).
:- use_module(library(filesex)).
:- use_module(library(http/json)).

%   readme_not_example(?FirstLine, ?Why): the code blocks of README.md
%   that are no example to run, by the text of their first line.

readme_not_example("swipl server/oro_server.pl          # the server, on 127.0.0.1:6969 (HTTP on 6970), with the common-sense ontology",
                   'Setup: the server every test starts').
readme_not_example("swipl test/run_tests.pl",
                   'Setup and Tests: the suite itself').
readme_not_example("swipl server/oro_server.pl [--port=N] [--host=ADDR] [--ontology=FILE]...",
                   'Options: the synopsis').
readme_not_example("pip install ./clients/python        # or: PYTHONPATH=clients/python",
                   'installs into the user''s Python; the python examples run with its alternative, PYTHONPATH=clients/python').
readme_not_example("{\"conflict\":\"disjoint\",\"about\":[\"cow\",\"Animal\",\"Plant\"],\"asserted\":[\"cow rdf:type Animal\",\"cow rdf:type Plant\"],\"axioms\":[\"Animal owl:disjointWith Plant\"]}",
                   'Explanations: sample output (test_explain.pl checks it)').
readme_not_example("swipl bench/bench_full.pl [--sizes=10000,100000,1000000] [--pin=0] [--json=FILE]",
                   'Benchmarks: the synopsis').

%   readme_code_block(-Start, -Block): a code block of README.md; Start
%   is the line of its first line (of the opening ``` of a fenced one),
%   Block its lines (without the indent, or between the fences).

readme_code_block(Start, Block) :-
    readme_lines(Lines),
    readme_scan(Lines, 1, "", Blocks),
    member(Start-Block, Blocks).

readme_lines(Lines) :-
    test_checkout_path('README.md', File),
    read_file_to_string(File, Text, []),
    split_string(Text, "\n", "", Lines).

readme_scan([], _, _, []).
readme_scan([L|Ls], N, Prev, Blocks) :-
    (   sub_string(L, 0, _, _, "```")
    ->  append(Body, [Close|Rest], Ls),
        sub_string(Close, 0, _, _, "```"),
        !,
        Blocks = [N-Body|Blocks1],
        length(Body, Len),
        N1 is N + Len + 2,
        readme_scan(Rest, N1, Close, Blocks1)
    ;   Prev == "",
        sub_string(L, 0, _, _, "    ")
    ->  readme_indented([L|Ls], Body0),
        length(Body0, Len),
        length(Skip, Len),
        append(Skip, Rest, [L|Ls]),
        readme_trim_blank(Body0, Body),
        Blocks = [N-Body|Blocks1],
        N1 is N + Len,
        last(Skip, Last),
        readme_scan(Rest, N1, Last, Blocks1)
    ;   N1 is N + 1,
        readme_scan(Ls, N1, L, Blocks)
    ).

%   readme_block_marker(+Start, -Line, -Kind, -Args): the marker of the
%   block starting at line Start is on line Line.

readme_block_marker(Start, Line, Kind, Args) :-
    readme_lines(Lines),
    Before is Start - 1,
    between(1, Before, I),
    Line is Before + 1 - I,
    nth1(Line, Lines, Text),
    Text \== "",
    !,
    readme_marker(Text, Kind, Args).

%   readme_example(-Line, -Kind, -Args, -Block): a marked example of
%   README.md; Line is the line of its marker.

readme_example(Line, Kind, Args, Block) :-
    readme_code_block(Start, Block),
    readme_block_marker(Start, Line, Kind, Args).

readme_marker(Text, Kind, Args) :-
    split_string(Text, "", " ", [Trimmed]),
    string_concat("<!-- readme-test:", Rest0, Trimmed),
    string_concat(Rest, "-->", Rest0),
    split_string(Rest, " ", " ", Words0),
    exclude(==(""), Words0, [KindText|ArgTexts]),
    atom_string(Kind, KindText),
    maplist(atom_string, Args, ArgTexts).

%   readme_unlisted(-Start, -First): a block neither marked nor listed.

readme_unlisted(Start, First) :-
    readme_code_block(Start, [First|_]),
    \+ readme_block_marker(Start, _, _, _),
    \+ readme_not_example(First, _).

readme_skip_blank([L|Ls], Rest) :-
    L == "",
    !,
    readme_skip_blank(Ls, Rest).
readme_skip_blank(Ls, Ls).

readme_indented([L|Ls], [Body|Bs]) :-
    (   string_concat("    ", Body, L)
    ->  true
    ;   L == "",
        readme_skip_blank(Ls, [Next|_]),
        sub_string(Next, 0, 4, _, "    ")
    ->  Body = ""
    ),
    !,
    readme_indented(Ls, Bs).
readme_indented(_, []).

readme_trim_blank(Block0, Block) :-
    reverse(Block0, R0),
    readme_skip_blank(R0, R),
    reverse(R, Block).

                 /*******************************
                 *            TELNET            *
                 *******************************/

%   readme_exchanges(+Lines, -Exchanges): Request-Reply pairs of lines.

readme_exchanges([], []).
readme_exchanges([L|Ls], Xs) :-
    sub_string(L, 0, _, _, "$ "),
    !,
    readme_exchanges(Ls, Xs).
readme_exchanges(Lines, [Request-Reply|Xs]) :-
    append(Request, ["#end#"|Rest0], Lines),
    !,
    (   Request = [Method|_],
        string_lower(Method, "close")
    ->  Rest0 = [Line|Rest],
        Reply = [Line]
    ;   append(Reply0, ["#end#"|Rest], Rest0)
    ->  append(Reply0, ["#end#"], Reply)
    ),
    readme_exchanges(Rest, Xs).

readme_telnet(Args, Exchanges, Replies) :-
    test_cli_server(Args, Port, readme_session(Port, Exchanges, Replies), _).

readme_session(Port, Exchanges, Replies) :-
    setup_call_cleanup(
        tcp_connect('127.0.0.1':Port, Pair, []),
        ( stream_pair(Pair, In, Out),
          set_stream(In, encoding(utf8)),
          set_stream(Out, encoding(utf8)),
          maplist(readme_exchange(In, Out), Exchanges, Replies)
        ),
        close(Pair, [force(true)])).

readme_exchange(In, Out, Request-Expected, Reply) :-
    forall(member(Line, Request), format(Out, "~s~n", [Line])),
    format(Out, "#end#~n", []),
    flush_output(Out),
    length(Expected, N),
    length(Reply, N),
    maplist(read_line_to_string(In), Reply).

                 /*******************************
                 *            PROLOG            *
                 *******************************/

%   readme_goals(+Lines, -Goals): goal(Text, Solutions, Expected) for
%   each `?- ` line of Lines.

readme_goals([], []).
readme_goals([L|Ls], Goals) :-
    (   string_concat("?- ", Goal0, L)
    ->  readme_goal_text(Goal0, Ls, Goal, Ls1),
        readme_expected(Ls1, Expected, Rest),
        include(readme_more, Expected, More),
        length(More, NMore),
        N is NMore + 1,
        Goals = [goal(Goal, N, Expected)|Goals1],
        readme_goals(Rest, Goals1)
    ;   readme_goals(Ls, Goals)
    ).

%   readme_goal_text(+First, +Lines, -Goal, -Rest): a goal written on
%   one line, or continued on the next ones up to the one ending with
%   a full stop.

readme_goal_text(First, Lines, Goal, Rest) :-
    split_string(First, "", " ", [Text]),
    (   string_concat(Goal, ".", Text)
    ->  Rest = Lines
    ;   Lines = [Next|Lines1],
        split_string(Next, "", " ", [NextText]),
        atomic_list_concat([Text, NextText], ' ', Joined),
        readme_goal_text(Joined, Lines1, Goal, Rest)
    ).

readme_expected([L|Ls], [L|Es], Rest) :-
    \+ sub_string(L, 0, _, _, "?- "),
    \+ sub_string(L, 0, _, _, "$ "),
    !,
    readme_expected(Ls, Es, Rest).
readme_expected(Rest, [], Rest).

readme_more(Line) :-
    sub_string(Line, _, _, 0, " ;").

readme_toplevel(Goals, Transcripts) :-
    test_checkout_path('.', Checkout),
    test_fixture('readme_toplevel.pl', Runner),
    tmp_file(readme_session, Session),
    setup_call_cleanup(
        open(Session, write, S),
        forall(member(goal(G, N, _), Goals),
               format(S, "~q.~n", [goal(G, N)])),
        close(S)),
    setup_call_cleanup(
        process_create(path(timeout),
                       ['60', swipl, '-p', 'library=prolog', Runner, Session],
                       [ cwd(Checkout), stdout(pipe(Out)), stderr(null),
                         process(Pid)
                       ]),
        ( read_string(Out, _, Text),
          process_wait(Pid, _)
        ),
        close(Out)),
    delete_file(Session),
    split_string(Text, "\n", "", Lines),
    readme_transcripts(Lines, Transcripts).

readme_transcripts(Lines, [T|Ts]) :-
    append(T, ["<end>"|Rest], Lines),
    !,
    readme_transcripts(Rest, Ts).
readme_transcripts(_, []).

%   readme_mismatch(+Goal, +Transcript, -Mismatch): the first line where
%   the README and the run differ, or `none`.

readme_goal_ports(Ports, goal(G0, N, E), goal(G, N, E)) :-
    readme_ports(Ports, G0, G).

readme_mismatch(goal(Goal, _, Expected0), Transcript, Mismatch) :-
    (   append(Expected, ["..."], Expected0)
    ->  true
    ;   Expected = Expected0
    ),
    (   Expected == []
    ->  (   Transcript = [First|_],
            ( First == "false." ; sub_string(First, 0, _, _, "ERROR") )
        ->  Mismatch = Goal-First
        ;   Mismatch = none
        )
    ;   readme_prefix(Expected, Transcript, Mismatch0),
        (   Mismatch0 == none
        ->  Mismatch = none
        ;   Mismatch = Goal-Mismatch0
        )
    ).

readme_prefix([], _, none) :-
    !.
readme_prefix([E|Es], [T|Ts], Mismatch) :-
    E == T,
    !,
    readme_prefix(Es, Ts, Mismatch).
readme_prefix([E|_], Ts, expected(E)-got(T)) :-
    (   Ts = [T|_]
    ->  true
    ;   T = end
    ).

                 /*******************************
                 *        SERVERS, PORTS        *
                 *******************************/

%   readme_server(+Argv, +Dir, +Env, -Ports, :Goal): run `swipl Argv`
%   in Dir with the environment variables Env added (killed after 60 s
%   at most), read its listening lines, run Goal once, stop it.  Ports
%   is ports(Oro, Http, Kb), a port being `none` if not served.

:- meta_predicate readme_server(+, +, +, -, 0).

readme_server(Argv, Dir, Env, Ports, Goal) :-
    setup_call_cleanup(
        process_create(path(timeout), ['60', swipl|Argv],
                       [ stdout(pipe(Out)), stderr(null), cwd(Dir),
                         environment(Env), process(Pid)
                       ]),
        ( readme_listening(Out, ports(none, none, none), Ports),
          Ports = ports(Oro, _, _),
          (   integer(Oro)
          ->  once(Goal)
          ;   print_message(error, format("test_readme: swipl ~q did not listen",
                                          [Argv])),
              fail
          )
        ),
        ( process_kill(Pid),
          process_wait(Pid, _),
          close(Out)
        )).

readme_listening(Out, Ports0, Ports) :-
    read_line_to_string(Out, Line),
    (   Line == end_of_file
    ->  Ports = Ports0
    ;   readme_port_line(Line, Which, Port)
    ->  setarg(Which, Ports0, Port),
        (   Which == 3
        ->  Ports = Ports0
        ;   readme_listening(Out, Ports0, Ports)
        )
    ;   readme_listening(Out, Ports0, Ports)
    ).

readme_port_line(Line, Which, Port) :-
    (   sub_string(Line, 0, _, _, "oro listening on ")
    ->  Which = 1
    ;   sub_string(Line, 0, _, _, "oro web listening on ")
    ->  Which = 2
    ;   sub_string(Line, 0, _, _, "oro serving the KB-API on ")
    ->  Which = 3
    ),
    split_string(Line, ":", " /", Parts),
    last(Parts, PortText),
    number_string(Port, PortText).

%   readme_cli_server(+Options, -Ports, :Goal): the server of the
%   checkout with Options, on free ports.

:- meta_predicate readme_cli_server(+, -, 0).

readme_cli_server(Options, Ports, Goal) :-
    test_checkout_path('server/oro_server.pl', Server),
    test_checkout_path('.', Checkout),
    append([Server|Options], ['--port=0', '--http=0'], Argv),
    readme_server(Argv, Checkout, [], Ports, Goal).

%   readme_ports(+Ports, +Text0, -Text): the README's fixed ports in
%   Text0 replaced by the ones served.

readme_ports(ports(Oro, Http, Kb), Text0, Text) :-
    foldl(readme_port, ["6969"-Oro, "6970"-Http, "6971"-Kb], Text0, Text).

readme_port(Fixed-Port, Text0, Text) :-
    (   integer(Port)
    ->  atomic_list_concat(Parts, Fixed, Text0),
        atomic_list_concat(Parts, Port, Atom),
        atom_string(Atom, Text)
    ;   Text = Text0
    ).

%   readme_request(+Port, +Lines, -Reply): send one request, read its
%   reply (lines up to #end#, without it).

readme_request(Port, Lines, Reply) :-
    setup_call_cleanup(
        tcp_connect('127.0.0.1':Port, Pair, []),
        ( stream_pair(Pair, In, Out),
          set_stream(In, encoding(utf8)),
          set_stream(Out, encoding(utf8)),
          forall(member(L, Lines), format(Out, "~w~n", [L])),
          format(Out, "#end#~n", []),
          flush_output(Out),
          readme_reply(In, Reply)
        ),
        close(Pair, [force(true)])).

readme_reply(In, Reply) :-
    read_line_to_string(In, Line),
    (   ( Line == "#end#" ; Line == end_of_file )
    ->  Reply = []
    ;   Reply = [Line|Rest],
        readme_reply(In, Rest)
    ).

%   readme_words(+Command, -Words): Command split as sh would (spaces,
%   single and double quotes; nothing else).

readme_words(Command, Words) :-
    string_codes(Command, Codes),
    phrase(readme_words(Words0), Codes),
    maplist(atom_codes, Words, Words0).

readme_words(Ws) --> " ", !, readme_words(Ws).
readme_words([W|Ws]) --> readme_word(W), { W \== [] }, !, readme_words(Ws).
readme_words([]) --> [].

readme_word(W) --> "\"", !, readme_upto(0'", Q), readme_word(W0), { append(Q, W0, W) }.
readme_word(W) --> "'", !, readme_upto(0'', Q), readme_word(W0), { append(Q, W0, W) }.
readme_word([C|W]) --> [C], { C \== 0' }, !, readme_word(W).
readme_word([]) --> [].

readme_upto(End, []) --> [End], !.
readme_upto(End, [C|Cs]) --> [C], readme_upto(End, Cs).

                 /*******************************
                 *             SHELL            *
                 *******************************/

%   readme_commands(+Lines, -Commands): command(Text, Expected) for each
%   `$ ` line (joined with its `\` continuations), but a background
%   server (`... &`).

readme_commands([], []).
readme_commands([L|Ls], Commands) :-
    (   string_concat("$ ", C0, L)
    ->  readme_continued(C0, Ls, Command, Ls1),
        readme_output(Ls1, Expected, Rest),
        (   sub_string(Command, _, _, 0, " &")
        ->  Commands = Commands1
        ;   Commands = [command(Command, Expected)|Commands1]
        ),
        readme_commands(Rest, Commands1)
    ;   readme_commands(Ls, Commands)
    ).

readme_continued(C0, Lines, Command, Rest) :-
    split_string(C0, "", " ", [C]),
    (   string_concat(Head, "\\", C),
        Lines = [Next|Lines1]
    ->  split_string(Next, "", " ", [NextText]),
        atomic_list_concat([Head, NextText], '', Joined),
        readme_continued(Joined, Lines1, Command, Rest)
    ;   Command = C,
        Rest = Lines
    ).

readme_output([L|Ls], [L|Es], Rest) :-
    \+ sub_string(L, 0, _, _, "$ "),
    !,
    readme_output(Ls, Es, Rest).
readme_output(Rest, [], Rest).

readme_shell(Ports, command(Command0, Expected0), Mismatch) :-
    readme_ports(Ports, Command0, Command),
    test_checkout_path('.', Checkout),
    setup_call_cleanup(
        process_create(path(timeout), ['30', sh, '-c', Command],
                       [ cwd(Checkout), stdout(pipe(Out)), stderr(null),
                         process(Pid)
                       ]),
        ( read_string(Out, _, Text0),
          process_wait(Pid, Status)
        ),
        close(Out)),
    split_string(Text0, "", "\n", [Text1]),
    atomic_list_concat(Parts, '\r', Text1),
    atomic_list_concat(Parts, '', Text),
    split_string(Text, "\n", "", Lines),
    (   append(Expected, ["..."], Expected0)
    ->  true
    ;   Expected = Expected0
    ),
    (   Status \== exit(0)
    ->  Mismatch = Command0-Status
    ;   readme_prefix(Expected, Lines, Mismatch0),
        (   Mismatch0 == none
        ->  Mismatch = none
        ;   Mismatch = Command0-Mismatch0
        )
    ).

                 /*******************************
                 *        SEVERAL NODES         *
                 *******************************/

%   readme_nodes(+Servers, +Client, -Lines): run the commands of
%   Servers (each `CMD &`), wait for the two nodes, run the script
%   Client, its last command until it shows cup1; Lines is that
%   command's output (the script's other output is discarded).  One
%   bash script, whose EXIT and TERM traps stop the background
%   processes, bounded by timeout(1).

readme_nodes(Servers, Client, Lines) :-
    maplist(readme_free_port, [Redis, A, B]),
    Ports = ["6380"-Redis, "7001"-A, "7002"-B],
    atomic_list_concat(Servers, '\n', ServersText0),
    atomic_list_concat(Client, '\n', ClientText0),
    foldl(readme_port, Ports, ServersText0, ServersText),
    foldl(readme_port, Ports, ClientText0, ClientText),
    split_string(ClientText, "\n", "", ClientLines),
    append(Before, [Last], ClientLines),
    atomic_list_concat(Before, '\n', BeforeText),
    format(string(Script),
           "exec 4>&1 >/dev/null 2>&1~n\c
            trap 'kill $(jobs -p) 2>/dev/null' EXIT TERM~n~w~n\c
            for i in $(seq 200); do \c
              (exec 3<>/dev/tcp/127.0.0.1/~w) 2>/dev/null && \c
              (exec 3<>/dev/tcp/127.0.0.1/~w) 2>/dev/null && break; \c
              sleep 0.1; done~n\c
            ~w~n\c
            for i in $(seq 100); do out=$(~w); \c
              case \"$out\" in *cup1*) break;; esac; sleep 0.1; done~n\c
            printf '%s\\n' \"$out\" >&4~n",
           [ServersText, A, B, BeforeText, Last]),
    test_checkout_path('.', Checkout),
    setup_call_cleanup(
        process_create(path(timeout), ['90', bash, '-c', Script],
                       [ cwd(Checkout), stdout(pipe(Out)), stderr(null),
                         process(Pid)
                       ]),
        ( read_string(Out, _, Text),
          process_wait(Pid, _)
        ),
        close(Out)),
    split_string(Text, "\n", "\n", Lines0),
    exclude(==(""), Lines0, Lines1),
    maplist(atom_string, Lines, Lines1).

%   readme_free_port(-Port): a port of 127.0.0.1 free now.

readme_free_port(Port) :-
    tcp_socket(Socket),
    tcp_bind(Socket, '127.0.0.1':Port),
    tcp_close_socket(Socket).

                 /*******************************
                 *        SERVER COMMANDS       *
                 *******************************/

%   readme_serve_argv(+Words, +Checkout, -Argv): the arguments of swipl
%   for the README's command Words, on free ports.

readme_serve_argv([swipl|Words0], Checkout, Argv) :-
    maplist(readme_serve_word(Checkout), Words0, Words1),
    (   member(W, Words1), sub_atom(W, 0, _, _, '--port=')
    ->  Extra0 = []
    ;   Extra0 = ['--port=0']
    ),
    (   member(W, Words1),
        ( sub_atom(W, 0, _, _, '--http') ; W == '--no-http' )
    ->  Extra = Extra0
    ;   append(Extra0, ['--http=0'], Extra)
    ),
    (   Words1 = ['-g'|_]
    ->  atom_concat('library=', Checkout, Lib0),
        atom_concat(Lib0, '/prolog', Lib),
        append(Words1, Extra, Words2),
        Argv = ['-p', Lib|Words2]
    ;   append(Words1, Extra, Argv)
    ).

%   readme_serve_word(+Checkout, +Word0, -Word): the server's script and
%   the files of --ontology and --plugin are the checkout's, whatever
%   the directory the command runs in; --port=6969 is a free port.

readme_serve_word(Checkout, Word0, Word) :-
    (   Word0 == '--port=6969'
    ->  Word = '--port=0'
    ;   Word0 == 'server/oro_server.pl'
    ->  atom_concat(Checkout, '/server/oro_server.pl', Word)
    ;   member(Option, ['--ontology=', '--plugin=']),
        atom_concat(Option, File, Word0),
        \+ sub_atom(File, 0, _, _, '/')
    ->  atomic_list_concat([Option, Checkout, '/', File], Word)
    ;   Word = Word0
    ).

readme_serve_methods(Ports, Methods) :-
    Ports = ports(Port, _, _),
    readme_request(Port, [listSimpleMethods], Reply),
    assertion(Reply = ["ok"|_]),
    atomic_list_concat(Reply, '\n', Text),
    forall(member(M, Methods),
           assertion(sub_atom(Text, _, _, _, M))).

                 /*******************************
                 *        CONFIG AND LOG        *
                 *******************************/

%   readme_config(+Block, +Dir, -FileName, -Settings, -Argv): the
%   settings file of the block and the command using it, for a run in
%   Dir.

readme_config(Block, Dir, Name, Settings, Argv) :-
    once(append([Head|Settings0], ["", Command], Block)),
    string_concat("% ", Name, Head),
    maplist(readme_config_line, Settings0, Settings),
    test_checkout_path('.', Checkout),
    readme_words(Command, Words0),
    maplist(readme_config_word(Dir), Words0, Words1),
    readme_serve_argv(Words1, Checkout, Argv0),
    exclude(==('--port=0'), Argv0, Argv1),
    append(Argv1, ['--kb-port=0'], Argv).

readme_config_line(Line0, Line) :-
    (   sub_string(Line0, 0, _, _, "setting(port,")
    ->  Line = "setting(port, 0)."
    ;   Line = Line0
    ).

readme_config_word(Dir, Word0, Word) :-
    (   sub_atom(Word0, 0, _, _, '--log=')
    ->  file_base_name(Word0, Base),
        atomic_list_concat(['--log=', Dir, '/', Base], Word)
    ;   Word = Word0
    ).

readme_with_tmp_dir(Dir, Goal) :-
    tmp_file(readme, Dir),
    setup_call_cleanup(
        make_directory(Dir),
        Goal,
        delete_directory_and_contents(Dir)).

%   readme_log_lines(+File, +N, -Lines): the first N lines of the log
%   File, once it has them (10 s at most).

readme_log_lines(File, N, Lines) :-
    between(1, 100, _),
    readme_file_lines(File, Lines1),
    include(readme_request_line, Lines1, Lines0),
    length(Lines0, Len),
    (   Len >= N
    ->  true
    ;   sleep(0.1),
        fail
    ),
    !,
    length(Lines, N),
    append(Lines, _, Lines0).

%   the lines of requests (not the load summaries)

readme_request_line(Line) :-
    sub_string(Line, _, _, _, " method=").

readme_file_lines(File, Lines) :-
    (   exists_file(File)
    ->  read_file_to_string(File, Text, []),
        split_string(Text, "\n", "", Lines0),
        exclude(==(""), Lines0, Lines)
    ;   Lines = []
    ).

%   readme_log_request(?Method, ?Request): the request the log-format
%   test sends for a sample line of Method.

readme_log_request(find, [find, o, '[?o isAt kitchen_table]']).
readme_log_request(getLabel, [getLabel, no_such_thing_at_all]).

%   readme_log_shape(+Line, -Shape): what a log line must share with
%   the README's sample: the time's format, the keys, and the values of
%   peer, method and the outcome.

readme_log_shape(Line, [Time|Fields]) :-
    split_string(Line, " ", "", [Stamp|Words]),
    (   string_length(Stamp, 24),
        sub_string(Stamp, 10, 1, _, "T"),
        sub_string(Stamp, 19, 1, _, "."),
        sub_string(Stamp, 23, 1, _, "Z")
    ->  Time = iso_ms
    ;   Time = Stamp
    ),
    maplist(readme_log_field, Words, Fields).

readme_log_field(Word, Field) :-
    (   sub_string(Word, B, _, A, "=")
    ->  sub_string(Word, 0, B, _, Key),
        sub_string(Word, _, A, 0, Value),
        (   memberchk(Key, ["conn", "ms"])
        ->  Field = Key
        ;   Field = Key-Value
        )
    ;   Field = Word
    ).

                 /*******************************
                 *       PYTHON, PLUGIN, PACK   *
                 *******************************/

readme_has_python :-
    catch(process_create(path(python3), ['-c', 'pass'],
                         [stdout(null), stderr(null), process(Pid)]),
          _, fail),
    process_wait(Pid, exit(0)).

readme_python(Block, Ports, Output, Expected) :-
    readme_with_tmp_dir(Dir,
        readme_python(Dir, Block, Ports, Output, Expected)).

readme_python(Dir, Block, Ports, Output, Expected) :-
    atomic_list_concat(Block, '\n', Text0),
    readme_ports(Ports, Text0, Text),
    atom_concat(Dir, '/example.py', Script),
    atom_concat(Dir, '/expected.txt', ExpectedFile),
    setup_call_cleanup(open(Script, write, S, [encoding(utf8)]),
                       format(S, "~w~n", [Text]),
                       close(S)),
    test_fixture('readme_python.py', Runner),
    test_checkout_path('clients/python', PyPath),
    Ports = ports(Port, _, _),
    setup_call_cleanup(
        process_create(path(timeout), ['30', python3, Runner, Script, ExpectedFile],
                       [ cwd(Dir), stdout(pipe(Out)), stderr(null),
                         environment([ 'PYTHONPATH'=PyPath,
                                       'ORO_HOST'='127.0.0.1',
                                       'ORO_PORT'=Port
                                     ]),
                         process(Pid)
                       ]),
        ( set_stream(Out, encoding(utf8)),
          read_string(Out, _, OutText),
          process_wait(Pid, Status)
        ),
        close(Out)),
    assertion(Status == exit(0)),
    split_string(OutText, "\n", "", Output0),
    exclude(==(""), Output0, Output),
    read_file_to_string(ExpectedFile, ExpText, [encoding(utf8)]),
    split_string(ExpText, "\n", "", Expected0),
    exclude(==(""), Expected0, Expected).

readme_plugin(Block, Method, Class, Count, Instances) :-
    readme_with_tmp_dir(Dir,
        ( atom_concat(Dir, '/plugin.pl', File),
          setup_call_cleanup(open(File, write, S),
                             forall(member(L, Block), format(S, "~s~n", [L])),
                             close(S)),
          atom_concat('--plugin=', File, Option),
          readme_cli_server([Option], ports(Port, _, _),
                            ( readme_request(Port, [Method, Class], Count),
                              readme_request(Port, [getInstancesOf, Class],
                                             Instances)
                            ))
        )).

%   readme_pack(+Goals, -Answer): run the pack_install/2 goals with the
%   checkout for /path/to/oro and a fresh HOME, then ask library(oro)
%   from another directory.

readme_pack(Goals, Answer) :-
    readme_with_tmp_dir(Dir,
        ( atom_concat(Dir, '/data', Data),
          atom_concat(Dir, '/elsewhere', Elsewhere),
          make_directory(Elsewhere),
          Env = ['HOME'=Dir, 'XDG_DATA_HOME'=Data],
          test_checkout_path('.', Checkout),
          forall(member(goal(G0, _, _), Goals),
                 ( atomic_list_concat(Parts, '/path/to/oro', G0),
                   atomic_list_concat(Parts, Checkout, G),
                   readme_swipl(['-g', G, '-t', halt], Elsewhere, Env, _, Status),
                   assertion(Status == exit(0))
                 )),
          readme_swipl([ '-g', 'use_module(library(oro)), oro_init([]), oro_find(myself, x, ["?x rdf:type Agent"], L), print(L), nl',
                         '-t', halt
                       ], Elsewhere, Env, Answer, _)
        )).

readme_swipl(Argv, Dir, Env, Output, Status) :-
    setup_call_cleanup(
        process_create(path(timeout), ['60', swipl|Argv],
                       [ cwd(Dir), stdout(pipe(Out)), stderr(null),
                         environment(Env), process(Pid)
                       ]),
        ( read_string(Out, _, Output),
          process_wait(Pid, Status)
        ),
        close(Out)).

                 /*******************************
                 *            TESTS             *
                 *******************************/

:- begin_tests(readme).

test(every_block_is_run_or_listed, Unlisted == []) :-
    findall(Line-First, readme_unlisted(Line, First), Unlisted).

test(every_listed_block_exists, Stale == []) :-
    findall(First, ( readme_not_example(First, _),
                     \+ readme_code_block(_, [First|_])
                   ), Stale).

test(every_marker_is_known, Unknown == []) :-
    findall(Line-Kind,
            ( readme_example(Line, Kind, _, _),
              \+ memberchk(Kind, [ telnet, prolog, 'prolog-client', shell,
                                   serve, config, 'log-format', python,
                                   plugin, pack, 'nodes-start', nodes
                                 ])
            ), Unknown).

test(example, [ forall(readme_example(Line, telnet, Args, Block)),
                true(Line-Replies == Line-Expected)
              ]) :-
    once(readme_exchanges(Block, Exchanges)),
    pairs_values(Exchanges, Expected),
    once(readme_telnet(Args, Exchanges, Replies)).

test(example, [ forall(readme_example(Line, prolog, _, Block)),
                true(Line-Mismatches == Line-[])
              ]) :-
    readme_goals(Block, Goals),
    readme_toplevel(Goals, Transcripts),
    length(Goals, N),
    length(Transcripts, NT),
    assertion(NT == N),
    maplist(readme_mismatch, Goals, Transcripts, Mismatches0),
    exclude(==(none), Mismatches0, Mismatches).

test(example, [ forall(readme_example(Line, 'prolog-client', Args, Block)),
                true(Line-Mismatches == Line-[])
              ]) :-
    readme_goals(Block, Goals0),
    readme_cli_server(Args, Ports,
        ( maplist(readme_goal_ports(Ports), Goals0, Goals),
          readme_toplevel(Goals, Transcripts)
        )),
    length(Goals, N),
    length(Transcripts, NT),
    assertion(NT == N),
    maplist(readme_mismatch, Goals, Transcripts, Mismatches0),
    exclude(==(none), Mismatches0, Mismatches).

test(example, [ forall(readme_example(Line, shell, Args, Block)),
                true(Line-Mismatches == Line-[])
              ]) :-
    readme_commands(Block, Commands),
    assertion(Commands \== []),
    readme_cli_server(Args, Ports,
        maplist(readme_shell(Ports), Commands, Mismatches0)),
    exclude(==(none), Mismatches0, Mismatches).

test(example, [ forall(readme_example(Line, serve, Methods, [Command])),
                true(Line-Served == Line-true)
              ]) :-
    readme_words(Command, Words),
    test_checkout_path('.', Checkout),
    readme_serve_argv(Words, Checkout, Argv),
    readme_with_tmp_dir(Dir,
        readme_server(Argv, Dir, [], Ports,
                      readme_serve_methods(Ports, Methods))),
    Served = true.

test(example, [ forall(readme_example(Line, config, _, Block)),
                true(Line-Port-Logged == Line-free-true)
              ]) :-
    readme_with_tmp_dir(Dir,
        ( readme_config(Block, Dir, Name, Settings, Argv),
          atomic_list_concat([Dir, '/', Name], File),
          setup_call_cleanup(open(File, write, S),
                             forall(member(L, Settings), format(S, "~s~n", [L])),
                             close(S)),
          readme_server(Argv, Dir, [], ports(P, _, _),
                        readme_request(P, [stats], Reply)),
          assertion(Reply = ["ok"|_]),
          directory_files(Dir, Files),
          include([F]>>sub_atom(F, _, _, 0, '.log'), Files, [Log]),
          atomic_list_concat([Dir, '/', Log], LogFile),
          readme_log_lines(LogFile, 1, _)
        )),
    (   P \== 6969
    ->  Port = free
    ;   Port = P
    ),
    Logged = true.

test(example, [ forall(readme_example(Line, 'log-format', _, Block)),
                true(Line-Shapes == Line-Expected)
              ]) :-
    maplist(readme_log_shape, Block, Expected),
    readme_with_tmp_dir(Dir,
        ( atom_concat(Dir, '/requests.log', File),
          atom_concat('--log=', File, Option),
          readme_cli_server([Option], ports(Port, _, _),
              forall(( member(L, Block),
                       sub_string(L, B, _, _, "method="),
                       B1 is B + 7,
                       sub_string(L, B1, _, 0, Rest),
                       split_string(Rest, " ", "", [M|_]),
                       atom_string(Method, M),
                       readme_log_request(Method, Request)
                     ),
                     readme_request(Port, Request, _))),
          length(Block, N),
          readme_log_lines(File, N, Lines)
        )),
    maplist(readme_log_shape, Lines, Shapes).

test(example, [ forall(readme_example(Line, python, Args, Block)),
                true(Line-Output == Line-Expected)
              ]) :-
    (   readme_has_python
    ->  readme_cli_server(Args, Ports,
                          readme_python(Block, Ports, Output, Expected))
    ;   print_message(informational,
                      format("test_readme: no python3, line ~w skipped", [Line])),
        Output = Expected
    ).

test(example, [ forall(readme_example(Line, plugin, [Method, Class], Block)),
                true(Line-Count == Line-["ok", N])
              ]) :-
    readme_plugin(Block, Method, Class, Count, ["ok", InstancesText]),
    setup_call_cleanup(open_string(InstancesText, In),
                       json_read(In, json(Instances)),
                       close(In)),
    length(Instances, Len),
    number_string(Len, N).

test(example, [ forall(readme_example(Line, pack, _, Block)),
                true(Line-Answer == Line-"[oro:myself]\n")
              ]) :-
    readme_goals(Block, Goals),
    assertion(Goals \== []),
    readme_pack(Goals, Answer).

test(example, [ forall(readme_example(Line, 'nodes-start', _, _)),
                true(Line-Followed == Line-true)
              ]) :-
    (   readme_example(Next, nodes, _, _),
        Next > Line,
        aggregate_all(count,
                      ( readme_code_block(Between, _),
                        Between > Line,
                        Between < Next
                      ),
                      1)                    % its own block only
    ->  Followed = true
    ;   Followed = false
    ).

test(example, [ forall(readme_example(Line, nodes, Expected, Block)),
                true(Line-Lines == Line-Expected)
              ]) :-
    (   absolute_file_name(path('redis-server'), _,
                           [access(execute), file_errors(fail)])
    ->  once(( readme_example(Start, 'nodes-start', _, Servers),
               Start < Line
             )),
        readme_nodes(Servers, Block, Lines)
    ;   format(user_error, "~NREADME line ~w: no redis-server, skipped~n",
               [Line]),
        Lines = Expected
    ).

:- end_tests(readme).
