:- prolog_load_context(directory, Dir), atom_concat(Dir, '/../prolog', Lib), ( user:file_search_path(library, Lib) -> true ; asserta(user:file_search_path(library, Lib)) ).
:- use_module(library(plunit)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).
:- use_module(library(aggregate)).
:- use_module(library(error)).
:- use_module(library(readutil)).
:- use_module(library(process)).
:- use_module(library(http/json)).
:- prolog_load_context(directory, Dir),
   atom_concat(Dir, '/oro_test_client', Client),
   use_module(Client),
   atom_concat(Dir, '/../server/oro_server', Server),
   use_module(Server),
   atom_concat(Dir, '/../server/oro_plugins', Plugins),
   use_module(Plugins).

/*  Tests of plugins (server/oro_plugins.pl), over real sockets on
    127.0.0.1: loading with plugin(File) options of oro_server_start/2,
    listing in listMethods, listSimpleMethods, methods and help,
    calling (parameters, context, transactions), run-time errors,
    clashes with built-in methods, files that cannot be loaded, and the
    real command line with --plugin.

    The method table is process-wide: every unit unloads its plugins in
    its cleanup (oro_unload_plugins/0), so no plugin leaks into the
    other test files.  The messages plugins cause while a unit starts
    its server are recorded (plg_message/2) instead of printed.

    Run: cd /work/main && swipl -g run_tests -t halt test/test_plugins.pl
*/

:- dynamic
    plg_test_dir/1,                     % Dir
    plg_server/1,                       % Server
    plg_capturing/1,                    % Thread
    plg_message/2.                      % Kind, Message

:- prolog_load_context(directory, Dir),
   retractall(plg_test_dir(_)),
   assertz(plg_test_dir(Dir)).


                 /*******************************
                 *     SERVER AND MESSAGES      *
                 *******************************/

%   While plg_capturing(Thread) holds, the messages printed by Thread
%   (the plugin loader's and the loader's own) are kept, not printed:
%   oro_plugin(Message) ones in plg_message/2.

:- multifile user:message_hook/3.
:- dynamic user:message_hook/3.

user:message_hook(Term, Kind, _) :-
    thread_self(Me),
    plg_capturing(Me),
    memberchk(Kind, [error, warning, informational]),
    (   Term = oro_plugin(Message)
    ->  assertz(plg_message(Kind, Message))
    ;   true
    ).

%   plg_start(+Plugins): start a server on the test ontology with the
%   plugins Plugins (files under test/fixtures/plugins/, or paths
%   relative to the checkout), recording the messages.

plg_start(Plugins) :-
    plg_stop,
    retractall(plg_message(_, _)),
    plg_fixture('testsuite.ttl', Ontology),
    maplist(plg_plugin_path, Plugins, Files),
    findall(plugin(F), member(F, Files), Options),
    thread_self(Me),
    setup_call_cleanup(
        assertz(plg_capturing(Me)),
        oro_server_start([ port(0), host('127.0.0.1'), commonsense(false),
                           ontology(Ontology)
                         | Options
                         ], Server),
        retractall(plg_capturing(Me))),
    assertz(plg_server(Server)).

plg_stop :-
    forall(retract(plg_server(Server)),
           ( plg_wait_connections(Server),
             oro_server_stop(Server)
           )),
    oro_unload_plugins.

%   plg_wait_connections(+Server): wait (10 s at most) until the
%   workers have seen their clients leave.

plg_wait_connections(Server) :-
    (   is_dict(Server),
        get_dict(pool, Server, Pool)
    ->  plg_wait_until(plg_pool_idle(Pool), 10)
    ;   true
    ).

plg_pool_idle(Pool) :-
    catch(thread_pool_property(Pool, running(0)), _, true).

plg_wait_until(Condition, Seconds) :-
    get_time(Now),
    Deadline is Now + Seconds,
    plg_wait_until_(Condition, Deadline).

plg_wait_until_(Condition, Deadline) :-
    (   call(Condition)
    ->  true
    ;   get_time(Now),
        Now < Deadline
    ->  sleep(0.01),
        plg_wait_until_(Condition, Deadline)
    ;   true
    ).

plg_fixture(File, Path) :-
    plg_test_dir(Dir),
    atomic_list_concat([Dir, '/fixtures/', File], Path).

plg_checkout_path(Relative, Path) :-
    plg_test_dir(Dir),
    atomic_list_concat([Dir, '/../', Relative], Path0),
    absolute_file_name(Path0, Path).

plg_plugin_path(Plugin, Path) :-
    (   sub_atom(Plugin, _, _, _, /)
    ->  plg_checkout_path(Plugin, Path)
    ;   atomic_list_concat(['plugins/', Plugin, '.pl'], Fixture),
        plg_fixture(Fixture, Path)
    ).

%   plg_load_captured(+File): oro_load_plugin/1, recording the
%   messages (of this load only).

plg_load_captured(File) :-
    retractall(plg_message(_, _)),
    thread_self(Me),
    setup_call_cleanup(
        assertz(plg_capturing(Me)),
        oro_load_plugin(File),
        retractall(plg_capturing(Me))).

%   plg_messages(-Messages): the oro_plugin messages of the last
%   start, as Kind-Functor pairs.

plg_messages(Messages) :-
    findall(Kind-Name,
            ( plg_message(Kind, Message),
              functor(Message, Name, _)
            ),
            Messages).


                 /*******************************
                 *          REQUESTS            *
                 *******************************/

plg_port(Port) :-
    plg_server(Server),
    !,
    oro_server_port(Server, Port).

%   plg_call(+Method, +Params, -Reply): one request on its own
%   connection.

plg_call(Method, Params, Reply) :-
    plg_port(Port),
    setup_call_cleanup(
        oro_connect(Port, Conn),
        oro_call(Conn, Method, Params, Reply),
        oro_disconnect(Conn)).

plg_ok(Method, Params, Value) :-
    plg_call(Method, Params, Reply),
    (   Reply = ok(Value)
    ->  true
    ;   throw(plg_unexpected_reply(Method, Reply))
    ).

plg_error_name(Reply, Name) :-
    (   Reply = error(Name0, _)
    ->  Name = Name0
    ;   Name = Reply
    ).

%   plg_json(+Line, -Value): the value line as JSON (strings as strings,
%   objects as Key-Value pairs with string keys).

plg_json(Line, Value) :-
    setup_call_cleanup(
        open_string(Line, In),
        json_read_dict(In, Value0, [value_string_as(string)]),
        close(In)),
    plg_json_value(Value0, Value).

plg_json_value(Dict, Pairs) :-
    is_dict(Dict),
    !,
    dict_pairs(Dict, _, Pairs0),
    findall(K-V, ( member(K0-V, Pairs0), atom_string(K0, K) ), Pairs).
plg_json_value(Value, Value).

%   The signatures listed by listSimpleMethods (or methods), the keys
%   of listMethods, the text of help.

plg_simple_methods(Method, Signatures) :-
    plg_ok(Method, [], Line),
    plg_json(Line, Signatures).

plg_method_keys(Keys) :-
    plg_ok(listMethods, [], Line),
    plg_json(Line, Pairs),
    pairs_keys(Pairs, Keys).

plg_help_text(Text) :-
    plg_ok(help, [], Text).

plg_listed_by_all(Signature, Listings) :-
    plg_simple_methods(listSimpleMethods, Simple),
    plg_simple_methods(methods, Methods),
    plg_method_keys(Keys),
    plg_help_text(Help),
    findall(Where,
            (   memberchk(Signature, Simple), Where = listSimpleMethods
            ;   memberchk(Signature, Methods), Where = methods
            ;   memberchk(Signature, Keys), Where = listMethods
            ;   sub_string(Help, _, _, _, Signature), Where = help
            ),
            Listings).

plg_is_plugin_signature(Signature) :-
    (   sub_string(Signature, 0, _, _, "plg")
    ;   sub_string(Signature, 0, _, _, "count")
    ),
    !.

%   plg_int(+Value, -N): an ok value line that is an integer.

plg_int(Line, N) :-
    number_string(N, Line),
    integer(N).


                 /*******************************
                 *      LOADING AND LISTING     *
                 *******************************/

:- begin_tests(plg_loading,
               [ setup(plg_start([good_plugin,
                                  'examples/plugins/count_instances.pl'])),
                 cleanup(plg_stop)
               ]).

test(loaded_messages, true(Messages == [ informational-loaded,
                                         informational-loaded
                                       ])) :-
    plg_messages(Messages).
test(registered, all(Module-Signatures ==
                     [ plg_good_plugin-[ plgEcho(string), plgSize(set),
                                         plgPeer, plgAddPair(string, string),
                                         plgFail, plgThrowIso(string),
                                         plgThrowOther
                                       ],
                       count_instances-[ countInstancesOf(string),
                                         countDirectInstancesOf(string)
                                       ]
                     ])) :-
    oro_plugin(_, Module, Signatures).
test(listed_everywhere, true(Listings == [ listSimpleMethods, methods,
                                           listMethods, help
                                         ])) :-
    plg_listed_by_all("countInstancesOf(String)", Listings).
test(listed_with_set_and_pairs, true(Listings == [ listSimpleMethods, methods,
                                                   listMethods, help
                                                 ])) :-
    plg_listed_by_all("plgAddPair(String, String)", Listings).
test(help_text_and_category, true(Found == true)) :-
    plg_help_text(Help),
    (   sub_string(Help, _, _, _, "testing"),
        sub_string(Help, _, _, _,
                   "countInstancesOf(String): Returns the number of instances")
    ->  Found = true
    ;   Found = false
    ).
test(listmethods_help, true(Help == "Returns the number of elements of a set.")) :-
    plg_ok(listMethods, [], Line),
    plg_json(Line, Pairs),
    memberchk("plgSize(Set)"-Help, Pairs).
test(builtins_still_listed, true(Listed == true)) :-
    plg_simple_methods(listSimpleMethods, Simple),
    (   memberchk("add(Set)", Simple),
        memberchk("find(String, Set)", Simple)
    ->  Listed = true
    ;   Listed = false
    ).

:- end_tests(plg_loading).


                 /*******************************
                 *            CALLING           *
                 *******************************/

:- begin_tests(plg_calling,
               [ setup(plg_start([good_plugin,
                                  'examples/plugins/count_instances.pl'])),
                 cleanup(plg_stop)
               ]).

test(string_param, true(Reply == ok("\"hello world\""))) :-
    plg_call(plgEcho, ["hello world"], Reply).
test(quoted_string_param, true(Reply == ok("\"hello\""))) :-
    plg_call(plgEcho, ["\"hello\""], Reply).
test(set_param, true(Reply == ok("3"))) :-
    plg_call(plgSize, ["[a, b, c]"], Reply).
test(case_insensitive_name, true(Reply == ok("2"))) :-
    plg_call(plgsize, ["[a, b]"], Reply).
test(context, true(Reply == ok("true"))) :-
    plg_call(plgPeer, [], Reply).
test(count_instances, true(Count == Listed)) :-
    plg_ok(countInstancesOf, ["Animal"], Line),
    plg_int(Line, Count),
    plg_ok(getInstancesOf, ["Animal"], Map),
    plg_json(Map, Pairs),
    length(Pairs, Listed).
test(count_direct_instances, true(Count == Listed)) :-
    plg_ok(countDirectInstancesOf, ["Monkey"], Line),
    plg_int(Line, Count),
    plg_ok(getDirectInstancesOf, ["Monkey"], Map),
    plg_json(Map, Pairs),
    length(Pairs, Listed).
test(count_sees_inferences, [ setup(plg_ok(reset, [], _)),
                              cleanup(plg_ok(reset, [], _)),
                              true(After =:= Before + 1)
                            ]) :-
    plg_ok(countInstancesOf, ["Animal"], Line0),
    plg_int(Line0, Before),
    plg_ok(add, ["[plgKong rdf:type Monkey]"], _),
    plg_ok(countInstancesOf, ["Animal"], Line),
    plg_int(Line, After).
test(count_unknown_class,
     true(Name == "com.hp.hpl.jena.shared.NotFoundException")) :-
    plg_call(countInstancesOf, ["plgNoSuchClass"], Reply),
    plg_error_name(Reply, Name).
test(transaction_applies_both, [ setup(plg_ok(reset, [], _)),
                                 cleanup(plg_ok(reset, [], _)),
                                 true(Checks == ["true", "true"])
                               ]) :-
    plg_ok(plgAddPair, ["plgA rdf:type Monkey", "plgA isOn plgB"], _),
    plg_ok(check, ["[plgA rdf:type Monkey]"], C1),
    plg_ok(check, ["[plgA isOn plgB]"], C2),
    Checks = [C1, C2].
test(transaction_applies_none, [ setup(plg_ok(reset, [], _)),
                                 cleanup(plg_ok(reset, [], _)),
                                 true(Name-Check ==
                                      "laas.openrobots.ontology.exceptions.IllegalStatementException"-"false")
                               ]) :-
    plg_call(plgAddPair, ["plgA rdf:type Monkey", "plgA isOn"], Reply),
    plg_error_name(Reply, Name),
    plg_ok(check, ["[plgA rdf:type Monkey]"], Check).

:- end_tests(plg_calling).


                 /*******************************
                 *        RUN-TIME ERRORS       *
                 *******************************/

:- begin_tests(plg_errors,
               [ setup(plg_start([good_plugin, undefined_plugin])),
                 cleanup(plg_stop)
               ]).

test(failing, true(Name == "laas.openrobots.ontology.exceptions.OntologyServerException")) :-
    plg_call(plgFail, [], Reply),
    plg_error_name(Reply, Name).
test(iso_error_mapped, true(Name == "com.hp.hpl.jena.shared.NotFoundException")) :-
    plg_call(plgThrowIso, ["Unicorn"], Reply),
    plg_error_name(Reply, Name).
test(non_iso_error, true(Name-Has == "laas.openrobots.ontology.exceptions.OntologyServerException"-true)) :-
    plg_call(plgThrowOther, [], Reply),
    Reply = error(Name, Message),
    (   sub_string(Message, _, _, _, "plg_not_an_iso_error")
    ->  Has = true
    ;   Has = false
    ).
test(undefined_implementation_warned, true(Messages == [ warning-undefined,
                                                         informational-loaded,
                                                         informational-loaded
                                                       ])) :-
    plg_messages(Messages0),
    msort(Messages0, Messages1),
    reverse(Messages1, Messages).
test(undefined_implementation_call, true(Name == "laas.openrobots.ontology.exceptions.OntologyServerException")) :-
    plg_call(plgUndefined, ["x"], Reply),
    plg_error_name(Reply, Name).
test(wrong_arity, true(Name == "NotImplementedException")) :-
    plg_call(plgEcho, ["a", "b"], Reply),
    plg_error_name(Reply, Name).
test(bad_set_param, true(Name == "NotImplementedException")) :-
    plg_call(plgSize, ["not a set"], Reply),
    plg_error_name(Reply, Name).
test(server_keeps_running, true(Replies == [ ok("\"oro-server 0.8.2\""),
                                             ok("\"still\"")
                                           ])) :-
    plg_call(plgThrowOther, [], _),
    plg_call(plgFail, [], _),
    plg_call(hello, [], R1),
    plg_call(plgEcho, ["still"], R2),
    Replies = [R1, R2].

:- end_tests(plg_errors).


                 /*******************************
                 *            CLASHES           *
                 *******************************/

:- begin_tests(plg_clashes,
               [ setup(plg_start([clash_plugin])),
                 cleanup(plg_stop)
               ]).

test(messages, true(Messages == [ warning-clash, warning-clash,
                                  warning-clash, warning-bad_declaration,
                                  informational-loaded
                                ])) :-
    plg_messages(Messages).
test(clash_names, all(S-Owner == [ add(set)-built_in, 'ADD'(set)-built_in,
                                   plgTwice(string)-this_plugin
                                 ])) :-
    plg_message(warning, clash(_, S, _, Owner)).
test(registered, true(Signatures == [plgTwice(string), plgClashOk(string)])) :-
    oro_plugin(_, plg_clash_plugin, Signatures).
test(builtin_add_wins, true(Replies == [ok(""), ok("true")])) :-
    plg_call(add, ["[plgX rdf:type Monkey]"], R1),
    plg_call(check, ["[plgX rdf:type Animal]"], R2),
    Replies = [R1, R2].
test(builtin_add_upper_case_wins, true(Reply == ok(""))) :-
    plg_call('ADD', ["[plgY rdf:type Monkey]"], Reply).
test(first_declaration_wins, true(Reply == ok("\"first\""))) :-
    plg_call(plgTwice, ["x"], Reply).
test(listed_once, true(N == 1)) :-
    plg_simple_methods(listSimpleMethods, Simple),
    aggregate_all(count, member("plgTwice(String)", Simple), N).
test(add_listed_once, true(N == 1)) :-
    plg_simple_methods(listSimpleMethods, Simple),
    aggregate_all(count, ( member(S, Simple),
                           string_lower(S, "add(set)")
                         ), N).
test(malformed_not_listed, true(Found == false)) :-
    plg_simple_methods(listSimpleMethods, Simple),
    (   member(S, Simple),
        sub_string(S, 0, _, _, "plgBadType")
    ->  Found = true
    ;   Found = false
    ).
test(clash_with_other_plugin, true(Owner-Reply == plugin(Clash)-ok("\"first\""))) :-
    plg_plugin_path(clash_plugin, Clash),
    plg_plugin_path(clash_other_plugin, Other),
    plg_load_captured(Other),
    plg_message(warning, clash(_, plgclashok(string), _, Owner)),
    plg_call(plgClashOk, ["x"], Reply).
test(reload_no_self_clash, true(Clashes == [add(set), 'ADD'(set), plgTwice(string)])) :-
    plg_plugin_path(clash_plugin, Clash),
    plg_load_captured(Clash),
    findall(S, plg_message(warning, clash(_, S, _, _)), Clashes).

:- end_tests(plg_clashes).


                 /*******************************
                 *      FILES THAT DO NOT LOAD  *
                 *******************************/

:- begin_tests(plg_load_errors,
               [ setup(plg_start([ syntax_error_plugin,
                                   directive_error_plugin,
                                   not_a_module_plugin,
                                   good_plugin
                                 ])),
                 cleanup(plg_stop)
               ]).

test(server_started, true(Reply == ok("\"oro-server 0.8.2\""))) :-
    plg_call(hello, [], Reply).
test(messages, true(Failed-Loaded == 3-1)) :-
    aggregate_all(count, plg_message(error, load_failed(_, _)), Failed),
    aggregate_all(count, plg_message(informational, loaded(_, _)), Loaded).
test(nothing_half_registered, true(Listed == [])) :-
    plg_simple_methods(listSimpleMethods, Simple),
    findall(S, ( member(S, Simple),
                 member(Prefix, ["plgSyntax", "plgDirective", "plgNotModule"]),
                 sub_string(S, 0, _, _, Prefix)
               ),
            Listed).
test(not_callable, true(Names == [ "NotImplementedException",
                                   "NotImplementedException"
                                 ])) :-
    plg_call(plgSyntax, ["x"], R1),
    plg_call(plgDirective, ["x"], R2),
    maplist(plg_error_name, [R1, R2], Names).
test(not_registered, true(Files == [Good])) :-
    plg_plugin_path(good_plugin, Good0),
    absolute_file_name(Good0, Good),
    findall(File, oro_plugin(File, _, _), Files).
test(good_one_works, true(Reply == ok("\"ok\""))) :-
    plg_call(plgEcho, ["ok"], Reply).
test(missing_file, true(Messages-Listed == [error-not_found]-false)) :-
    plg_load_captured('/nonexistent/plg_missing.pl'),
    plg_messages(Messages),
    (   oro_plugin('/nonexistent/plg_missing.pl', _, _)
    ->  Listed = true
    ;   Listed = false
    ).

test(ordinary_file_refused, true(Messages-Listed == [error-not_a_plugin]-false)) :-
    plg_load_captured(library(lists)),
    plg_messages(Messages),
    (   oro_plugin(File, _, _),
        sub_atom(File, _, _, 0, 'lists.pl')
    ->  Listed = true
    ;   Listed = false
    ).

:- end_tests(plg_load_errors).


                 /*******************************
                 *          UNLOADING           *
                 *******************************/

:- begin_tests(plg_unloading,
               [ setup(plg_start([good_plugin,
                                  'examples/plugins/count_instances.pl'])),
                 cleanup(plg_stop)
               ]).

test(unload_one, true(Left-Reply == [count_instances]-"NotImplementedException")) :-
    plg_plugin_path(good_plugin, Good),
    oro_unload_plugin(Good),
    findall(M, oro_plugin(_, M, _), Left),
    plg_call(plgEcho, ["x"], R),
    plg_error_name(R, Reply).
test(unload_all, true(Left-Listed == []-[])) :-
    oro_unload_plugins,
    findall(M, oro_plugin(_, M, _), Left),
    plg_simple_methods(listSimpleMethods, Simple),
    include(plg_is_plugin_signature, Simple, Listed).
test(reload_after_unload, true(Reply == ok("\"again\""))) :-
    plg_plugin_path(good_plugin, Good),
    plg_load_captured(Good),
    plg_call(plgEcho, ["again"], Reply).

:- end_tests(plg_unloading).


                 /*******************************
                 *         COMMAND LINE         *
                 *******************************/

%   plg_with_cli_server(+Args, -Port, :Goal, -Stderr): run the real
%   command line (swipl server/oro_server.pl --port=0 Args) as a child
%   process, wait for its listening line, run Goal, stop the server;
%   Stderr is what it printed meanwhile.

:- meta_predicate plg_with_cli_server(+, -, 0, -).

plg_with_cli_server(Args, Port, Goal, Stderr) :-
    plg_checkout_path('server/oro_server.pl', Server),
    plg_checkout_path('.', Checkout),
    setup_call_cleanup(
        process_create(path(timeout), ['60', swipl, Server, '--port=0'|Args],
                       [ stdout(pipe(Out)), stderr(pipe(Err)),
                         cwd(Checkout), process(Pid)
                       ]),
        ( read_line_to_string(Out, Line),
          (   split_string(Line, ":", " ", Parts),
              last(Parts, PortText),
              number_string(Port, PortText)
          ->  call(Goal)
          ;   Port = none
          )
        ),
        ( process_kill(Pid),
          process_wait(Pid, _),
          read_string(Err, _, Stderr),
          close(Out),
          close(Err)
        )).

plg_cli_call(Port, Method, Params, Reply) :-
    setup_call_cleanup(
        oro_connect(Port, Conn),
        oro_call(Conn, Method, Params, Reply),
        oro_disconnect(Conn)).

plg_cli_args(Plugins, Args) :-
    plg_fixture('testsuite.ttl', Ontology),
    atom_concat('--ontology=', Ontology, OntologyArg),
    findall(A, ( member(P, Plugins), atom_concat('--plugin=', P, A) ), PArgs),
    append(['--no-commonsense', OntologyArg], PArgs, Args).

:- begin_tests(plg_command_line).

test(count_instances_plugin, true(Reply-Loaded == ok("2")-true)) :-
    plg_cli_args(['examples/plugins/count_instances.pl'], Args),
    plg_with_cli_server(Args, Port,
                        plg_cli_call(Port, countInstancesOf, ["Monkey"], Reply),
                        Stderr),
    (   sub_string(Stderr, _, _, _, "count_instances.pl loaded")
    ->  Loaded = true
    ;   Loaded = false
    ).
test(bad_plugin_server_starts, true(Reply-Reported == ok("\"oro-server 0.8.2\"")-true)) :-
    plg_cli_args(['test/fixtures/plugins/syntax_error_plugin.pl'], Args),
    plg_with_cli_server(Args, Port,
                        plg_cli_call(Port, hello, [], Reply),
                        Stderr),
    (   sub_string(Stderr, _, _, _, "syntax_error_plugin.pl not loaded")
    ->  Reported = true
    ;   Reported = false
    ).
test(help_mentions_plugin, true(Has == true)) :-
    plg_checkout_path('server/oro_server.pl', Server),
    setup_call_cleanup(
        process_create(path(timeout), ['30', swipl, Server, '--help'],
                       [ stdout(pipe(Out)), process(Pid) ]),
        ( read_string(Out, _, Help),
          process_wait(Pid, _)
        ),
        close(Out)),
    (   sub_string(Help, _, _, _, "--plugin=FILE")
    ->  Has = true
    ;   Has = false
    ).

:- end_tests(plg_command_line).
