/*  Tests of the command line: swipl server/oro_server.pl [options],
    run as a child process, as a user would.
*/

:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(process)).
:- use_module(library(readutil)).
:- use_module(library(socket)).
:- use_module(library(apply)).
:- use_module('../server/oro_server').

%!  cli_run(+Args, -ExitCode, -Output) is det.
%
%   Run the server with Args until it exits by itself (at most 30 s);
%   Output is stdout and stderr.

cli_run(Args, Code, Output) :-
    test_checkout_path('server/oro_server.pl', Server),
    setup_call_cleanup(
        process_create(path(timeout), ['30', swipl, Server|Args],
                       [ stdout(pipe(Out)), stderr(pipe(Err)),
                         process(Pid)
                       ]),
        ( read_string(Out, _, O),
          read_string(Err, _, E),
          process_wait(Pid, exit(Code))
        ),
        ( close(Out), close(Err) )),
    string_concat(O, E, Output).

%   request(+Port, +Lines, -Reply): send one request (the method and
%   its parameters, a line each) and read its three-line reply.

request(Port, Lines, Reply) :-
    setup_call_cleanup(
        tcp_connect('127.0.0.1':Port, Pair, []),
        ( stream_pair(Pair, In, Out),
          forall(member(Line, Lines), format(Out, "~w~n", [Line])),
          format(Out, "#end#~n", []),
          flush_output(Out),
          read_line_to_string(In, Status),
          read_line_to_string(In, Value),
          read_line_to_string(In, End),
          Reply = [Status, Value, End]
        ),
        close(Pair)).

shared_ontology(Name, Path) :-
    test_checkout_path('../shared/ontologies', Dir),
    directory_file_path(Dir, Name, Path),
    exists_file(Path).

:- begin_tests(command_line).

test(help, [true(Code-Has == 0-true)]) :-
    cli_run(['--help'], Code, Output),
    (   sub_string(Output, _, _, _, "--robot-id")
    ->  Has = true
    ;   Has = false
    ).
test(unknown_option, [true(Code \== 0)]) :-
    cli_run(['--bogus'], Code, _).
test(bad_port, [true(Code \== 0)]) :-
    cli_run(['--port=abc'], Code, _).
test(port_out_of_range, [true(Code-Said == 1-true)]) :-
    cli_run(['--port=65537'], Code, Output),
    test_bool(sub_string(Output, _, _, _, "0..65535"), Said).
test(port_out_of_range_in_prolog, error(domain_error(port, 70000))) :-
    oro_server_start([port(70000)], _).
test(bad_rebuild_garbage, [true(Code \== 0)]) :-
    cli_run(['--rebuild-garbage=-5'], Code, _).
test(zero_time_base, [true(Code-Said == 1-true)]) :-
    % A time unit of 0 ms is refused by the option parser, which names
    % the option and says what it takes.
    cli_run(['--time-base=0'], Code, Output),
    test_bool(sub_string(Output, _, _, _, "--time-base=0 requires a positive integer"),
              Said).
test(rebuild_garbage, [true(Reply == ["ok", "\"oro-server 0.8.2\"", "#end#"])]) :-
    test_cli_server(['--rebuild-garbage=0'], Port,
                    request(Port, [hello], Reply), _).

%   swipl takes the arguments right after a script whose names end in
%   .pl for more files to load: the server reads them all the same
%   (the README's plugin command), and refuses a bare file name.

test(plugin_option_first, [true(Reply == ["ok", "3", "#end#"])]) :-
    test_cli_server(['--plugin=examples/plugins/count_instances.pl',
                     '--no-commonsense', '--ontology=test/fixtures/testsuite.ttl'],
                    Port,
                    request(Port, [countInstancesOf, 'Animal'], Reply), _).
test(bare_file_name_refused, [true(Code-Said == 1-true)]) :-
    test_checkout_path('examples/plugins/count_instances.pl', Plugin),
    cli_run([Plugin], Code, Output),
    test_bool(sub_string(Output, _, _, _, "unexpected argument"), Said).
test(missing_ontology, [true(Code \== 0)]) :-
    cli_run(['--ontology=/nonexistent/x.owl'], Code, _).
test(listening_default_ontology, [true(Reply == ["ok", "\"oro-server 0.8.2\"", "#end#"])]) :-
    test_cli_server([], Port, request(Port, [hello], Reply), _).

%   The server loads the SPARQL engine once it listens (see oro_sparql):
%   a query sent at once is answered, after that load if it is still
%   running.

test(query_right_after_listening,
     [true(Reply == ["ok", "[\"Cup\"]", "#end#"])]) :-
    test_cli_server([], Port,
                    request(Port,
                            [ query, x,
                              "SELECT ?x WHERE { ?x rdfs:subClassOf oro:Cup }"
                            ],
                            Reply),
                    _).
test(no_commonsense_and_robot_id, [true(Reply == ["ok", "\"oro-server 0.8.2\"", "#end#"])]) :-
    test_checkout_path('test/fixtures/testsuite.ttl', Fixture),
    atom_concat('--ontology=', Fixture, Opt),
    test_cli_server(['--no-commonsense', Opt, '--robot-id=ROBOT',
                     '--time-base=100'],
                    Port, request(Port, [hello], Reply), _).

%   Loading the public ontologies prints nothing but the one-line
%   summary of each load.

test(public_ontologies_load_silently, [true(Other-Reply == []-["ok", "\"oro-server 0.8.2\"", "#end#"])]) :-
    (   shared_ontology('oro.owl', ORO),
        shared_ontology('testsuite.oro.owl', TS)
    ->  atom_concat('--ontology=', ORO, O1),
        atom_concat('--ontology=', TS, O2),
        test_cli_server([O1, O2], Port,
                        request(Port, [hello], Reply), Stderr),
        split_string(Stderr, "\n", "", Lines),
        exclude(cli_load_summary, Lines, Other)
    ;   format(user_error, "~NNotice: ../shared/ontologies absent: \c
                            skipping the public ontologies test~n", []),
        Other = [],
        Reply = ["ok", "\"oro-server 0.8.2\"", "#end#"]
    ).

cli_load_summary("").
cli_load_summary(Line) :-
    sub_string(Line, 0, _, _, "% oro: loaded ").


%   Exposing the server (--host other than loopback) warns on stderr
%   that the protocol has no authentication; the default bind does not.
%   The exposed server runs for the time of one hello, on a free port,
%   and is only ever reached through 127.0.0.1.

test(exposed_host_warns,
     [true(Reply-Warned == ["ok", "\"oro-server 0.8.2\"", "#end#"]-true)]) :-
    test_cli_server(['--host=0.0.0.0', '--no-commonsense'], Port,
                    request(Port, [hello], Reply), Stderr),
    test_bool(sub_string(Stderr, _, _, _, "no authentication"), Warned).
test(loopback_does_not_warn,
     [true(Reply-Warned == ["ok", "\"oro-server 0.8.2\"", "#end#"]-false)]) :-
    test_cli_server(['--no-commonsense'], Port,
                    request(Port, [hello], Reply), Stderr),
    test_bool(sub_string(Stderr, _, _, _, "authentication"), Warned).

%   --save-dir=DIR: save("x.owl") writes DIR/x.owl; a path going up out
%   of DIR or an absolute one, for the robot's model or an agent's, gets
%   an error and writes nothing; the saved file loads back with
%   --ontology.

test(save_dir,
     [ setup(cli_save_dir(Dir)),
       cleanup(delete_directory_and_contents(Dir)),
       true(Got == [ ok(""), ok(""), ok(""), true,
                     error, error, error, false,
                     ok("true")
                   ])
     ]) :-
    file_base_name(Dir, Base),
    atomic_list_concat(['"../', Base, '_up.owl"'], Up),
    atomic_list_concat([Dir, '_abs.owl'], Abs),
    format(atom(AbsParam), '"~w"', [Abs]),
    atomic_list_concat(['"../', Base, '_agent.owl"'], AgentUp),
    atom_concat('--save-dir=', Dir, SaveDir),
    cli_session([SaveDir],
                [ add-["[gerard rdf:type Human, book1 isOn shelf1]"],
                  save-["\"x.owl\""],
                  save-["gerard", "\"y.owl\""],
                  save-[Up],
                  save-[AbsParam],
                  save-["gerard", AgentUp]
                ],
                Replies),
    directory_file_path(Dir, 'x.owl', Saved),
    test_bool(exists_file(Saved), Written),
    atomic_list_concat([Dir, '_up.owl'], UpFile),
    atomic_list_concat([Dir, '_agent.owl'], AgentFile),
    test_bool(( member(F, [UpFile, Abs, AgentFile]), exists_file(F) ), Outside),
    atom_concat('--ontology=', Saved, Ontology),
    cli_session(['--no-commonsense', Ontology],
                [check-["[book1 isOn shelf1]"]], Checked),
    (   Replies = [Add, SaveX, SaveY, E1, E2, E3],
        Checked = [Check]
    ->  maplist(cli_reply_kind, [E1, E2, E3], Errors),
        append([[Add, SaveX, SaveY, Written], Errors, [Outside, Check]], Got)
    ;   Got = Replies-Checked
    ).

test(save_dir_missing, [true(Code \== 0)]) :-
    cli_run(['--save-dir=/nonexistent/oro-save-dir'], Code, _).

cli_save_dir(Dir) :-
    tmp_file(oro_cli_save, Dir),
    make_directory(Dir).

%   cli_session(+Args, +Requests, -Replies): run the server with Args
%   and the Method-Params Requests in order on one connection; Replies
%   is no_server(Stderr) if it did not start.

cli_session(Args, Requests, Replies) :-
    test_cli_server(Args, Port, cli_calls(Port, Requests, Replies0), Stderr),
    (   Port == none
    ->  Replies = no_server(Stderr)
    ;   Replies = Replies0
    ).

%   cli_calls(+Port, +Requests, -Replies): the Method-Params Requests in
%   order on one connection.

cli_calls(Port, Requests, Replies) :-
    setup_call_cleanup(
        oro_connect(Port, Conn),
        maplist(cli_call(Conn), Requests, Replies),
        oro_disconnect(Conn)).

cli_call(Conn, Method-Params, Reply) :-
    oro_call(Conn, Method, Params, Reply).

cli_reply_kind(Reply, Kind) :-
    (   Reply = error(_, _)
    ->  Kind = error
    ;   Kind = Reply
    ).

:- end_tests(command_line).
