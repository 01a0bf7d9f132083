:- module(oro_methods,
          [ oro_dispatch/4,             % +Context, +Method, +Params, -Reply
            oro_prepare/3,              % +Method, +Params, -Prepared
            oro_perform/3,              % +Context, +Prepared, -Reply
            oro_connection_closed/1,    % +Context
            oro_connection_events/1,    % +Context
            oro_reply_with_events/2,    % +Context, :Write
            oro_method_signature/2,     % ?Name, ?Signature
            oro_simple_signature/2      % +Signature, -Text
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(pairs)).
:- use_module(library(error)).
:- use_module(library(debug)).
:- use_module(library(http/json)).
:- use_module(library(aggregate)).
:- use_module(library(readutil)).
:- use_module(library(settings)).
:- use_module(library(oro)).
:- use_module(library(oro/parse/oro_parse)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/oro_errors)).
:- use_module(library(oro/server/oro_protocol)).

/** <module> The ORO method table and dispatcher

Every RPC method of the server is declared by one clause of the
multifile hook oro_methods:method/4 -- built-in methods and plugins
alike:

    method(Signature, Category, Help, Implementation)

  - Signature is Name(Type, ...) with each Type `string`, `set` or
    `list`, as ORO spells them in listSimpleMethods
    (`add(Set)`, `find(String, Set)`);
  - Category groups methods in `help`;
  - Help is a one-line description (a string);
  - Implementation is a callable, called as
    call(Implementation, Arg1, ..., ArgN, Reply) with the decoded
    parameters (strings for `String`, lists of strings for `Set` and
    `List`); Reply is a value term of oro_protocol (`void`,
    `bool(B)`, `string(S)`, `list(L)`, `map(Pairs)`, `raw(Text)`).
    An Implementation context(Goal) is called as
    call(Goal, Context, Arg1, ..., ArgN, Reply), Context being the
    dict describing the connection.  An Implementation
    transaction(Impl), Impl being one of the above, is called as one
    change of the store (oro_store_write/2, action method(Name)): the
    changes it makes, with any number of oro_add/2, oro_remove/2...
    calls, are committed together when it succeeds, and none is kept
    if it fails or raises.  The plugins' methods are called so (see
    oro_plugins).

The dispatcher finds the method by name (case-insensitively) and
arity, decodes the parameters, calls it, and turns any error into an
ORO error reply through oro_errors.  Only what is declared here is
listed by listMethods, listSimpleMethods and help.
*/

:- setting(reply_events_wait, number, 2,
           'Seconds a reply to a connection with watchers waits at most \c
           for the watcher thread to evaluate the request''s changes, so \c
           that their events are written with it; events that take \c
           longer follow the reply').

:- multifile method/4.
:- discontiguous method/4.

%!  method(?Signature, ?Category, ?Help, ?Implementation) is nondet.
%
%   The method table; see the module documentation.

		 /*******************************
		 *          DISPATCH            *
		 *******************************/

%!  oro_dispatch(+Context, +Method, +Params, -Reply) is det.
%
%   Execute the request Method(Params) (Method a string as received,
%   Params a list of strings).  Reply is ok(Value) or
%   error(ExceptionName, Message).

oro_dispatch(Context, Method, Params, Reply) :-
    reply(dispatch(Context, Method, Params, Value), Value, Reply).

%!  oro_prepare(+Method, +Params, -Prepared) is det.
%
%   The part of the request Method(Params) that does not depend on the
%   store, done ahead: the method found, its parameters decoded, and
%   the statements a method adds parsed (see statements_param/2).  The
%   server prepares a request while the one before it is being
%   answered, when a client sends them back to back.  Prepared is given
%   to oro_perform/3; it is prepared(Impl, Name, Args), or
%   request(Method, Params) when the preparation failed (the request is
%   then dispatched again by oro_perform/3, which answers with the
%   error), or failed(Error) when its parsing ran out of resources
%   (nesting, time: see oro_parse), which is then the reply.  A statement that does not parse is left as text, for the
%   method to reject.

oro_prepare(Method, Params, Prepared) :-
    (   catch(oro_parse_budget(prepare(Method, Params, Prepared0)), Error,
              true)
    ->  (   var(Error)
        ->  Prepared = Prepared0
        ;   Error = error(resource_error(_), _)     % would cost as much again
        ->  Prepared = failed(Error)
        ;   Prepared = request(Method, Params)
        )
    ;   Prepared = request(Method, Params)
    ).

prepare(Method, Params, prepared(Impl, Name, Args)) :-
    decoded(Method, Params, Sig, Impl, Name, Args0),
    (   statements_param(Sig, N)
    ->  parse_ahead(N, Args0, Args)
    ;   Args = Args0
    ).

%!  oro_perform(+Context, +Prepared, -Reply) is det.
%
%   Execute a request prepared by oro_prepare/3 for the connection
%   Context; Reply as for oro_dispatch/4.

oro_perform(Context, request(Method, Params), Reply) :-
    !,
    oro_dispatch(Context, Method, Params, Reply).
oro_perform(Context, prepared(Impl, Name, Args), Reply) :-
    reply(call_method(Impl, Name, Context, Args, Value), Value, Reply).
oro_perform(_, failed(Error), Reply) :-
    reply(throw(Error), _, Reply).

%   reply(:Goal, ?Value, -Reply): the outcome of Goal, which binds Value,
%   as a reply.  The parsing Goal does runs within one parse budget
%   (oro_parse_budget/1).

reply(Goal, Value, Reply) :-
    (   catch(oro_parse_budget(Goal), Error, true)
    ->  true
    ;   Error = error(oro_method(failed), _)
    ),
    (   var(Error)
    ->  Reply = ok(Value)
    ;   Error = oro_connection_end(_)       % the connection must close
    ->  throw(Error)
    ;   oro_error_response(Error, Name, Message),
        debug(oro(server), 'Error: ~q', [Error]),
        Reply = error(Name, Message)
    ).

dispatch(Context, Method, Params, Value) :-
    decoded(Method, Params, _, Impl, Name, Args),
    call_method(Impl, Name, Context, Args, Value).

%   decoded(+Method, +Params, -Sig, -Impl, -Name, -Args): the method
%   called Method (method_for/5) and its parameters decoded as its
%   signature Sig declares them.

decoded(Method, Params, Sig, Impl, Name, Args) :-
    method_for(Method, Params, Sig, Impl, Name),
    Sig =.. [_|Types],
    decode_params(Types, Params, Method, Args).

%   method_for(+Method, +Params, -Sig, -Impl, -Name): the method called
%   Method with as many parameters as Params: its declared signature,
%   implementation and name.

method_for(Method, Params, Skeleton, Impl, Exact) :-
    length(Params, Arity),
    atom_string(Exact, Method),
    functor(Skeleton, Exact, Arity),
    method(Skeleton, _, _, Impl),           % the usual case: exact name
    !.
method_for(Method, Params, Sig, Impl, Declared) :-
    string_lower(Method, Lower),
    atom_string(Name, Lower),
    findall(Sig0-Impl0, named_method(Name, Sig0, Impl0), Candidates),
    length(Params, Arity),
    (   Candidates == []
    ->  throw(error(oro_method(unknown, Method), _))
    ;   include(has_arity(Arity), Candidates, [Sig-Impl|_])
    ->  functor(Sig, Declared, _)
    ;   throw(error(oro_method(arity(Arity), Method), _))
    ).

%   statements_param(?Signature, ?N): the Nth parameter of the built-in
%   method Signature is a set of statements it adds (oro_add/3,
%   oro_update/2), which may be given parsed, as rdf/3 terms.

statements_param(add(set), 1).
statements_param(add(set, string), 1).
statements_param(update(set), 1).
statements_param(addForAgent(string, set), 2).
statements_param(addForAgent(string, set, string), 2).
statements_param(updateForAgent(string, set), 2).

%   parse_ahead(+N, +Args0, -Args): the Nth argument, statements as
%   text, replaced by their triples if they are all complete statements.
%   (oro_statements/3 normalises such triples again, at a fifth of the
%   cost of parsing them: git log of bench/RESULTS.md.)

parse_ahead(N, Args0, Args) :-
    nth1(N, Args0, Statements, Rest),
    (   catch(oro_statements(Statements, Triples, []), Error,
              rethrow_resource(Error)),
        ground(Triples)
    ->  nth1(N, Args, Triples, Rest)
    ;   Args = Args0
    ).

%   rethrow_resource(+Error): throw Error if it is a resource error, else
%   fail (the method parses the statements again and rejects them).

rethrow_resource(Error) :-
    (   Error = error(resource_error(_), _)
    ->  throw(Error)
    ;   fail
    ).

named_method(Lower, Sig, Impl) :-
    method(Sig, _, _, Impl),
    functor(Sig, Name, _),
    downcase_atom(Name, Lower).

has_arity(Arity, Sig-_) :-
    functor(Sig, _, Arity).

decode_params(Types, Params, Method, Args) :-
    catch(maplist(decode_param, Types, Params, Args),
          error(type_error(Type, _), _),
          (   collection_type(Type)
          ->  throw(error(oro_method(prototype, Method), _))
          ;   fail
          )).

collection_type(oro_collection).
collection_type(oro_map).

decode_param(string, Text, Value) :-
    oro_clean_value(Text, Value).
decode_param(set, Text, Value) :-
    oro_parse_collection(set, Text, Value).
decode_param(list, Text, Value) :-
    oro_parse_collection(list, Text, Value).

%   call_method(+Impl, +Name, +Context, +Args, -Value): call the
%   implementation of the method Name.  A transaction(Impl) runs as one
%   store write: rdf_db transactions nest, so the changes Impl makes
%   join it and the store's monitors (journal, watchers) see one change
%   when it commits; a failure or exception rolls them all back.

call_method(transaction(Impl), Name, Context, Args, Value) :-
    !,
    oro_store_write(method(Name),
                    call_method(Impl, Name, Context, Args, Value)).
call_method(context(Goal), _, Context, Args, Value) :-
    !,
    append([Context|Args], [Value], AllArgs),
    call_reply(Goal, AllArgs).
call_method(Goal, _, _, Args, Value) :-
    append(Args, [Value], AllArgs),
    call_reply(Goal, AllArgs).

call_reply(Goal, Args) :-
    Call =.. [call, Goal|Args],
    (   call(Call)
    ->  true
    ;   throw(error(oro_method(failed), _))
    ).

%!  oro_method_signature(?Name, ?Signature) is nondet.
%
%   Signature is a declared method called Name.

oro_method_signature(Name, Signature) :-
    method(Signature, _, _, _),
    functor(Signature, Name, _).

%!  oro_simple_signature(+Signature, -Text) is det.
%
%   Text is the signature as listSimpleMethods spells it:
%   `find(String, Set)`.

oro_simple_signature(Signature, Text) :-
    Signature =.. [Name|Types],
    maplist(type_name, Types, Names),
    atomic_list_concat(Names, ', ', Args),
    format(string(Text), '~w(~w)', [Name, Args]).

type_name(string, 'String').
type_name(set, 'Set').
type_name(list, 'List').

		 /*******************************
		 *        ADMINISTRATION        *
		 *******************************/

method(help, base,
       "Lists the methods of the server with a short description.",
       m_help).
method(hello, administration,
       "Returns the name and version of the server.",
       m_hello).
method(stats, administration,
       "Returns statistics about the server: version, host, uptime...",
       context(m_stats)).
method(listMethods, administration,
       "Returns the methods of the server with their descriptions.",
       m_list_methods).
method(listSimpleMethods, administration,
       "Returns the signatures of the methods of the server.",
       m_list_simple_methods).
method(methods, administration,
       "Returns the signatures of the methods of the server (alias of listSimpleMethods).",
       m_list_simple_methods).
method(makeHtmlDoc, administration,
       "Returns an HTML page documenting the methods of the server.",
       m_html_doc).
method(reset, administration,
       "Forgets everything added since the server started: facts, agents, events.",
       m_reset).
method(clear, administration,
       "Without parameter: resets the server (same as reset).",
       m_reset).
method(save, administration,
       "Saves the robot's model as RDF/XML in a timestamped file of the save directory.",
       m_save).
method(save(string), administration,
       "Saves the robot's model as RDF/XML to the given file, under the save directory.",
       m_save).
method(list(string), administration,
       "Prints the asserted statements matching a pattern in the server's log.",
       m_list).

m_help(multiline_string(Text)) :-
    findall(Cat-(Sig-Help), method(Sig, Cat, Help, _), Pairs0),
    keysort(Pairs0, Pairs),
    group_pairs_by_key(Pairs, Groups),
    with_output_to(string(Text),
                   ( format("\e[1moro\e[0m: the ORO knowledge server, \c
                             in SWI-Prolog (ORO protocol 0.8.2)~n~n"),
                     forall(member(Cat-Methods, Groups),
                            ( format("\e[1m~w\e[0m~n", [Cat]),
                              forall(member(Sig-Help, Methods),
                                     ( oro_simple_signature(Sig, S),
                                       format("\t- ~w: ~w~n", [S, Help])
                                     ))
                            )),
                     format("~nSend the method name, one parameter per \c
                             line, then #end#.")
                   )).

m_hello(string("oro-server 0.8.2")).

%   stats: ORO's keys (values are strings, as clients parse them), with
%   real counts for nb_classes, nb_instances (of the robot's model) and
%   nb_clients, and more figures: the triples of the store, of each
%   model's layer (triples.Model.Layer) and of the ontology, the
%   models, the event watchers, the server's memory.  The server adds
%   its own figures through server_figure/2 (nb_clients).

:- multifile
    server_figure/2.                % -Key, -Value

m_stats(Context, map(Pairs)) :-
    get_time(Now),
    Uptime is max(0, integer(Now - Context.started)),
    H is Uptime // 3600,
    M is (Uptime mod 3600) // 60,
    S is Uptime mod 60,
    format(string(UptimeText), "~|~`0t~d~2+:~|~`0t~d~2+:~|~`0t~d~2+", [H, M, S]),
    gethostname(Host),
    aggregate_all(count, oro_class(myself, _), Classes),
    aggregate_all(count, oro_individual(myself, _), Instances),
    (   server_figure(connections, Clients)
    ->  true
    ;   Clients = "not available"
    ),
    store_figures(Figures),
    Pairs0 = [ "version"-"0.8.2",
               "host"-Host,
               "uptime"-UptimeText,
               "nb_classes"-Classes,
               "nb_instances"-Instances,
               "nb_clients"-Clients,
               "pending_requests"-"0"
             | Figures
             ],
    maplist(string_figure, Pairs0, Pairs).

string_figure(Key-Value, Key-string(Text)) :-
    format(string(Text), "~w", [Value]).

store_figures(Figures) :-
    rdf_statistics(triples(Triples)),
    oro_store_sizes(Sizes),
    findall(Key-N,
            ( member(size(Model, Layer, N), Sizes),
              Model \== ontology,
              layer_key(Layer, LayerName),
              format(string(Key), "triples.~w.~w", [Model, LayerName])
            ),
            LayerFigures),
    aggregate_all(sum(N), member(size(ontology, _, N), Sizes), Ontology),
    aggregate_all(count, oro_model(_), Models),
    aggregate_all(sum(N),
                  ( oro_model(Model),
                    oro_watchers(Model, Watchers),
                    length(Watchers, N)
                  ),
                  NWatchers),
    memory_bytes(Memory),
    append([ "triples"-Triples,
             "triples.ontology"-Ontology,
             "models"-Models,
             "watchers"-NWatchers,
             "memory_bytes"-Memory
           ],
           LayerFigures, Figures).

layer_key(profile(Profile), Profile) :- !.
layer_key(Layer, Layer).

%   memory_bytes(-Bytes): the resident memory of the process (Linux's
%   /proc/self/status), or what Prolog allocated elsewhere.

memory_bytes(Bytes) :-
    (   catch(read_file_to_string('/proc/self/status', Status, []), _, fail),
        sub_string(Status, B, _, _, "VmRSS:"),
        sub_string(Status, B, _, 0, Rest),
        split_string(Rest, "\n", "", [Line|_]),
        split_string(Line, " \t", " \t", Parts),
        member(Text, Parts),
        number_string(KB, Text)
    ->  Bytes is KB * 1024
    ;   statistics(memory, [Bytes|_])
    ).

m_list_methods(map(Pairs)) :-
    findall(Text-string(Help),
            ( method(Sig, _, Help, _),
              oro_simple_signature(Sig, Text)
            ),
            Pairs).

m_list_simple_methods(list(Signatures)) :-
    findall(string(Text),
            ( method(Sig, _, _, _),
              oro_simple_signature(Sig, Text)
            ),
            Signatures).

m_html_doc(string(HTML)) :-
    findall(Sig-Help, method(Sig, _, Help, _), Methods),
    with_output_to(string(HTML),
                   ( format("<h2>List of available methods</h2><ul>"),
                     forall(member(Sig-Help, Methods),
                            ( oro_simple_signature(Sig, S),
                              format("<li><b>~w</b>: ~w</li>", [S, Help])
                            )),
                     format("</ul>")
                   )).

m_reset(void) :-
    oro_reset.

m_save(void) :-
    get_time(Now),
    format_time(atom(File), '%Y%m%d-%H%M%S-snapshot.owl', Now),
    oro_save(myself, File).

m_save(Path, void) :-
    atom_string(File, Path),
    oro_save(myself, File).

m_list(Pattern, void) :-
    oro_statements([Pattern], [rdf(S, P, O)], _),
    forall(oro_asserted(myself, S, P, O),
           ( statement_text(rdf(S, P, O), Text),
             print_message(informational, format('~w', [Text]))
           )).

		 /*******************************
		 *        KNOWLEDGE BASE        *
		 *******************************/

method(add(set), base,
       "Adds statements to the robot's model (long-term memory).",
       m_add).
method(remove(set), base,
       "Removes statements (or statements matching patterns) from the robot's model.",
       m_remove).
method(retract(set), base,
       "Removes statements (alias of remove).",
       m_remove).
method(clear(set), base,
       "Removes every asserted statement matching one of the patterns.",
       m_clear).
method(update(set), base,
       "Adds statements, replacing the previous value of functional properties.",
       m_update).
method(check(set), base,
       "Tells whether every statement or pattern holds (asserted or inferred).",
       m_check).
method(find(string, set), querying,
       "Returns the values of a variable that satisfy all the patterns.",
       m_find).

m_add(Statements, void) :-
    oro_add(myself, Statements).

m_remove(Statements, void) :-
    oro_remove(myself, Statements).

m_clear(Patterns, void) :-
    oro_clear(myself, Patterns).

m_update(Statements, void) :-
    oro_update(myself, Statements).

m_check(Patterns, Bool) :-
    truth(oro_check(myself, Patterns), Bool).

m_find(Var, Patterns, Values) :-
    find_values(myself, Var, Patterns, Values).

term_string_value(Term, string(Text)) :-
    oro_term_text(Term, Text).

		 /*******************************
		 *       LABELS, LOOKUP         *
		 *******************************/

method(lookup(string), base,
       "Returns the [id, type] pairs whose label or name is the text (case-insensitive).",
       m_lookup).
method(lookup(string, string), base,
       "Returns the ids of the given type (instance, class, object_property, datatype_property) whose label or name is the text.",
       m_lookup).
method(getLabel(string), base,
       "Returns the label of a resource (else its name).",
       m_get_label).
method(getInfos(string), querying,
       "Returns the statements (asserted or inferred) about a resource.",
       m_get_infos).
method(about(string), querying,
       "Returns the statements about a resource (alias of getInfos).",
       m_get_infos).
method(getResourceDetails(string), querying,
       "Returns a JSON description of a resource: label, type, classes, properties...",
       m_resource_details).
method(getResourceDetails(string, string), querying,
       "Returns a JSON description of a resource, with labels in the given language.",
       m_resource_details).

m_lookup(Text, Pairs) :-
    lookup_pairs(myself, Text, Pairs).

lookup_pairs(Model, Text, list(Pairs)) :-
    oro_lookup(Model, Text, Matches),
    maplist(match_pair, Matches, Pairs).

match_pair(R-Kind, list([string(Id), string(Type)])) :-
    oro_iri_name(R, Id),
    upcase_atom(Kind, Type).

m_lookup(Text, TypeText, list(Ids)) :-
    string_lower(TypeText, Lower),
    atom_string(Kind, Lower),
    oro_lookup(myself, Text, Matches),
    findall(string(Id), ( member(R-Kind, Matches), oro_iri_name(R, Id) ), Ids).

m_get_label(Id, string(Label)) :-
    resource(Id, R),
    oro_label(myself, R, Label).

m_get_infos(Id, Infos) :-
    infos(myself, Id, Infos).

infos(Model, Id, list(Texts)) :-
    resource(Id, R),
    oro_infos(Model, R, Triples),
    maplist(local_statement, Triples, Texts0),
    list_to_set(Texts0, Texts).         % two triples may read the same

local_statement(rdf(S, P, O), string(Text)) :-
    oro_term_local_text(S, ST),
    oro_term_local_text(P, PT),
    oro_term_local_text(O, OT),
    atomic_list_concat([ST, PT, OT], ' ', Text).

m_resource_details(Id, raw(JSON)) :-
    resource(Id, R),
    oro_resource_details(myself, R, en, Details),
    details_json(Details, JSON).

m_resource_details(Id, Lang, raw(JSON)) :-
    resource(Id, R),
    atom_string(L, Lang),
    oro_resource_details(myself, R, L, Details),
    details_json(Details, JSON).

resource(Id, IRI) :-
    oro_name_iri(Id, IRI).

%   The JSON of getResourceDetails, in the exact layout oro-view reads.

details_json(D, JSON) :-
    json_string(D.name, Name),
    resource_json(D.id, Id),
    json_string(D.type, Type),
    maplist(resource_json, D.same_as, Same),
    atomic_list_concat(Same, ',', SameText),
    maplist(attribute_json, D.attributes, Attrs),
    atomic_list_concat(Attrs, ',', AttrText),
    format(string(JSON),
           '{"name":~w,"id":~w,"type":~w,"sameAs":[~w],"attributes": [~w]}',
           [Name, Id, Type, SameText, AttrText]).

attribute_json(attribute(Name, Id, Values), JSON) :-
    json_string(Name, N),
    json_string(Id, I),
    maplist(value_json, Values, Vs),
    atomic_list_concat(Vs, ',', VText),
    format(string(JSON), '{"name":~w,"id":~w,"values":[~w]}', [N, I, VText]).

value_json(value(Label, literal), JSON) :-
    !,
    json_string(Label, L),
    format(string(JSON), '{"name":~w, "id":"literal"}', [L]).
value_json(value(Label, R), JSON) :-
    json_string(Label, L),
    resource_json(R, I),
    format(string(JSON), '{"name":~w, "id":~w}', [L, I]).

%   resource_json(+R, -JSON): the id of a resource in the details, as
%   oro-server 0.8.2 gives it: the name of a resource of the default
%   namespace (`Monkey`), the full IRI of any other
%   (`http://xmlns.com/foaf/0.1/Person`, not `foaf:Person`).

resource_json(R, JSON) :-
    (   oro_default_namespace(NS),
        sub_atom(R, 0, _, _, NS)
    ->  oro_iri_name(R, Name)
    ;   rdf_is_bnode(R)
    ->  oro_iri_name(R, Name)
    ;   Name = R
    ),
    json_string(Name, JSON).

%   json_string(+Text, -JSON): a JSON string, escaped as the strings of
%   every reply (oro_encode_string/2): no escape liboro cannot read.

json_string(Text, JSON) :-
    oro_encode_string(Text, JSON).

		 /*******************************
		 *           TAXONOMY           *
		 *******************************/

method(getSuperclassesOf(string), taxonomy,
       "Returns all the super-classes of a class, with their labels.",
       m_taxonomy(oro_superclasses)).
method(getDirectSuperclassesOf(string), taxonomy,
       "Returns the direct super-classes of a class, with their labels.",
       m_taxonomy(oro_direct_superclasses)).
method(getSubclassesOf(string), taxonomy,
       "Returns all the sub-classes of a class, with their labels.",
       m_taxonomy(oro_subclasses)).
method(getDirectSubclassesOf(string), taxonomy,
       "Returns the direct sub-classes of a class, with their labels.",
       m_taxonomy(oro_direct_subclasses)).
method(getInstancesOf(string), taxonomy,
       "Returns all the instances of a class, with their labels.",
       m_taxonomy(oro_instances)).
method(getDirectInstancesOf(string), taxonomy,
       "Returns the instances whose most specific class is the given one, with their labels.",
       m_taxonomy(oro_direct_instances)).
method(getClassesOf(string), taxonomy,
       "Returns all the classes of an individual, with their labels.",
       m_taxonomy(oro_classes_of)).
method(getDirectClassesOf(string), taxonomy,
       "Returns the most specific classes of an individual, with their labels.",
       m_taxonomy(oro_direct_classes_of)).

m_taxonomy(Question, Id, map(Pairs)) :-
    resource(Id, R),
    call(Question, myself, R, Resources),
    maplist(labelled, Resources, Pairs).

labelled(R, Name-string(Label)) :-
    oro_iri_name(R, Name),
    oro_label(myself, R, Label).

		 /*******************************
		 *       AGENTS AND MEMORY      *
		 *******************************/

method(add(set, string), base,
       "Adds statements with a memory profile: SHORTTERM, EPISODIC, LONGTERM or DEFAULT.",
       m_add_profile).
method(listAgents, agents,
       "Returns the names of the agent models: myself, its aliases and the other agents.",
       m_list_agents).
method(addForAgent(string, set), agents,
       "Adds statements to an agent's model.",
       m_add_for_agent).
method(addForAgent(string, set, string), agents,
       "Adds statements to an agent's model with a memory profile.",
       m_add_for_agent).
method(safeAddForAgent(string, set), agents,
       "Adds the statements that keep an agent's model consistent; false if one was rejected.",
       m_safe_add_for_agent).
method(safeAddForAgent(string, set, string), agents,
       "Adds, with a memory profile, the statements that keep an agent's model consistent; false if one was rejected.",
       m_safe_add_for_agent).
method(checkConsistencyForAgent(string), agents,
       "Tells whether an agent's model is consistent.",
       m_check_consistency_for_agent).
method(safeAdd(set), base,
       "Adds the statements that keep the robot's model consistent; false if one was rejected.",
       m_safe_add).
method(safeAdd(set, string), base,
       "Adds, with a memory profile, the statements that keep the model consistent; false if one was rejected.",
       m_safe_add).
method(checkConsistency, base,
       "Tells whether the robot's model is consistent.",
       m_check_consistency).
method(checkConsistency(set), base,
       "Tells whether the robot's model would be consistent with the statements (nothing is kept).",
       m_check_consistency).
method(removeForAgent(string, set), agents,
       "Removes statements (or statements matching patterns) from an agent's model.",
       m_clear_for_agent).
method(clearForAgent(string, set), agents,
       "Removes every asserted statement matching one of the patterns from an agent's model.",
       m_clear_for_agent).
method(updateForAgent(string, set), agents,
       "Adds statements to an agent's model, replacing the values of functional properties.",
       m_update_for_agent).
method(findForAgent(string, string, set), agents,
       "Returns the values of a variable satisfying the patterns in an agent's model.",
       m_find_for_agent).
method(findForAgent(string, string, set, set), agents,
       "Returns the values of a variable satisfying the patterns and SPARQL filters in an agent's model.",
       m_find_for_agent).
method(find(set, set, set, set), querying,
       "KB-API find: one variable, patterns, SPARQL filters (or null) and one agent (or null for myself).",
       m_find_kb).
method(getInfosForAgent(string, string), agents,
       "Returns the statements about a resource in an agent's model.",
       m_get_infos_for_agent).
method(lookupForAgent(string, string), agents,
       "Returns the [id, type] pairs whose label or name is the text, in an agent's model.",
       m_lookup_for_agent).
method(save(string, string), agents,
       "Saves an agent's model as RDF/XML to the given file, under the save directory.",
       m_save_for_agent).
method(revise(set, string), base,
       "Applies statements to models as a JSON policy says: {\"method\": \"add\"|\"safe_add\"|\"retract\"|\"update\", \"models\": [...], \"memory_profile\": ...}.",
       m_revise).

m_add_profile(Statements, Profile, void) :-
    oro_add(myself, Statements, Profile).

m_list_agents(list(Names)) :-
    oro_agents(Agents),
    maplist(atom_string_value, Agents, Names).

atom_string_value(Atom, string(String)) :-
    atom_string(Atom, String).

m_add_for_agent(Agent, Statements, void) :-
    agent_model(Agent, Model),
    oro_add(Model, Statements).
m_add_for_agent(Agent, Statements, Profile, void) :-
    agent_model(Agent, Model),
    oro_add(Model, Statements, Profile).

m_safe_add_for_agent(Agent, Statements, bool(Accepted)) :-
    agent_model(Agent, Model),
    oro_safe_add(Model, Statements, longterm, Accepted).
m_safe_add_for_agent(Agent, Statements, Profile, bool(Accepted)) :-
    agent_model(Agent, Model),
    oro_safe_add(Model, Statements, Profile, Accepted).

m_check_consistency_for_agent(Agent, Bool) :-
    agent_model(Agent, Model),
    truth(oro_consistent(Model), Bool).

m_safe_add(Statements, bool(Accepted)) :-
    oro_safe_add(myself, Statements, longterm, Accepted).
m_safe_add(Statements, Profile, bool(Accepted)) :-
    oro_safe_add(myself, Statements, Profile, Accepted).

m_check_consistency(Bool) :-
    truth(oro_consistent(myself), Bool).
m_check_consistency(Statements, Bool) :-
    truth(oro_consistent_with(myself, Statements), Bool).

:- meta_predicate truth(0, -).

truth(Goal, bool(Bool)) :-
    (   call(Goal)
    ->  Bool = true
    ;   Bool = false
    ).

m_clear_for_agent(Agent, Patterns, void) :-
    agent_model(Agent, Model),
    oro_clear(Model, Patterns).

m_update_for_agent(Agent, Statements, void) :-
    agent_model(Agent, Model),
    oro_update(Model, Statements).

m_find_for_agent(Agent, Var, Patterns, Values) :-
    agent_model(Agent, Model),
    find_values(Model, Var, Patterns, Values).

m_find_for_agent(Agent, Var, Patterns, Filters, Values) :-
    agent_model(Agent, Model),
    find_filtered(Model, Var, Patterns, Filters, Values).

m_find_kb(Vars, Patterns, Filters, Agents, Values) :-
    length(Vars, NVars),
    (   NVars =:= 1
    ->  Vars = [Var]
    ;   throw(error(domain_error(oro_find_variables, NVars), _))
    ),
    (   Agents == []
    ->  Model = myself
    ;   Agents = [Agent]
    ->  agent_model(Agent, Model)
    ;   throw(error(domain_error(oro_find_agents, Agents), _))
    ),
    find_filtered(Model, Var, Patterns, Filters, Values).

%   Filters are SPARQL expressions, evaluated by oro_sparql.

find_filtered(Model, Var, Patterns, [], Values) :-
    !,
    find_values(Model, Var, Patterns, Values).
find_filtered(Model, Var, Patterns, Filters, list(Texts)) :-
    oro_find(Model, Var, Patterns, Filters, Values),
    distinct_texts(Values, Texts).

find_values(Model, Var, Patterns, list(Texts)) :-
    oro_find(Model, Var, Patterns, Values),
    distinct_texts(Values, Texts).

%   distinct_texts(+Values, -Texts): the texts of Values, each once, as
%   string(Text) reply values, in the order of the texts.  Distinct
%   values can have one text (`12` and `"12"`, `"robot"@en` and
%   `"robot"@fr`); ORO answers a set of strings.  (sort/2, on the path
%   of every find: 1 µs for 16 answers, list_to_set/2 5 µs.)

distinct_texts(Values, Texts) :-
    maplist(term_string_value, Values, Texts0),
    sort(Texts0, Texts).

m_get_infos_for_agent(Agent, Id, Infos) :-
    agent_model(Agent, Model),
    infos(Model, Id, Infos).

m_lookup_for_agent(Agent, Text, Pairs) :-
    agent_model(Agent, Model),
    lookup_pairs(Model, Text, Pairs).

m_save_for_agent(Agent, Path, void) :-
    agent_model(Agent, Model),
    atom_string(File, Path),
    oro_save(Model, File).

m_revise(Statements, PolicyText, void) :-
    catch(atom_json_dict(PolicyText, Policy, []), _,
          throw(error(domain_error(oro_revision_policy, PolicyText), _))),
    (   is_dict(Policy)
    ->  true
    ;   throw(error(domain_error(oro_revision_policy, PolicyText), _))
    ),
    oro_revise(Statements, Policy).

		 /*******************************
		 *            EVENTS            *
		 *******************************/

method(registerEvent(string, string, list), events,
       "Registers an event (FACT_CHECKING, NEW_INSTANCE, NEW_CLASS_INSTANCE) with a trigger (ON_TRUE, ON_TRUE_ONE_SHOT, ON_FALSE, ON_FALSE_ONE_SHOT, ON_TOGGLE) on patterns; returns its id.",
       context(m_register_event)).
method(registerEvent(string, string, string, list), events,
       "Registers an event whose variable (for NEW_INSTANCE) is given; returns its id.",
       context(m_register_event)).
method(registerEventForAgent(string, string, string, list), events,
       "Registers an event on an agent's model; returns its id.",
       context(m_register_event_for_agent)).
method(registerEventForAgent(string, string, string, string, list), events,
       "Registers an event with a variable on an agent's model; returns its id.",
       context(m_register_event_for_agent)).
method(clearEvents, events,
       "Removes every event of the robot's model, registered with registerEvent or registerEventForAgent.",
       m_clear_events).
method(clearEvent(string), events,
       "Removes the event with this id.",
       m_clear_event).
method(clearEventsForAgent(string), events,
       "Removes every event registered with registerEventForAgent on this agent.",
       m_clear_events_for_agent).
method(clearEvent(string, string), events,
       "Removes the event with this id registered with registerEventForAgent on this agent (an id from registerEvent or from another agent is not found there).",
       m_clear_event_for_agent).

m_register_event(Context, Type, Trigger, Patterns, raw(Id)) :-
    register_event(Context, plain, myself, Type, Trigger, '', Patterns, Id).
m_register_event(Context, Type, Trigger, Var, Patterns, raw(Id)) :-
    register_event(Context, plain, myself, Type, Trigger, Var, Patterns, Id).

m_register_event_for_agent(Context, Agent, Type, Trigger, Patterns, raw(Id)) :-
    agent_model(Agent, Model),
    register_event(Context, agent, Model, Type, Trigger, '', Patterns, Id).
m_register_event_for_agent(Context, Agent, Type, Trigger, Var, Patterns, raw(Id)) :-
    agent_model(Agent, Model),
    register_event(Context, agent, Model, Type, Trigger, Var, Patterns, Id).

register_event(Context, Registry, Model, Type, Trigger, Var, Patterns, Id) :-
    connection_subscriber(Context, Subscriber),
    oro_register_event(Model, Type, Trigger, Var, Patterns, Subscriber,
                       Registry, Id).

m_clear_events(void) :-
    oro_clear_events(myself).

m_clear_event(Id, void) :-
    oro_clear_event(myself, Id).

m_clear_events_for_agent(Agent, void) :-
    agent_model(Agent, Model),
    oro_clear_events(Model, agent).

%   clearEvent(agent, id) addresses the registry of
%   registerEventForAgent on the agent's model only, as
%   clearEventsForAgent does: the id of a plain registerEvent watcher
%   (or of another agent's) is EventNotFoundException, and that watcher
%   stays (ORO-SPEC §7.1 keeps the registries apart).

m_clear_event_for_agent(Agent, Id, void) :-
    agent_model(Agent, Model),
    oro_clear_event(Model, agent, Id).

agent_model(Agent, Model) :-
    atom_string(Name, Agent),
    oro_resolve_model(Name, Model).

%   CONNECTION EVENTS
%
%   A connection's events are written so that a client never finds an
%   event where it waits for a reply (ORO-SPEC §7.4; liboro reads the
%   reply at once after an event and takes its absence for a lost
%   connection):
%
%     - the events a request fires for the connection's own watchers
%       follow its reply in the same write, and the next request is
%       not answered before them;
%     - the events other connections' changes fire are written between
%       the connection's replies: with the reply when a request is in
%       progress, else by the connection's event writer as soon as they
%       are fired.
%
%   Each event is written once, in commit order.  The connection has
%   one subscriber for all its watchers (in every registry), made on
%   first registration with in_watcher(true): the watcher thread hands
%   it each firing at once, and it only puts the firing in the
%   connection's outbox (a bounded queue, the setting
%   oro_server:event_queue) and rings the writer's doorbell, never
%   waiting.  Whatever writes to the connection holds its mutex, and
%   the outbox is only emptied under it: by the worker after a reply
%   (oro_reply_with_events/2), which first waits for the watcher thread
%   to have processed the changes of its own request
%   (oro_events_sync_sent/0), or by the event writer, a thread of the
%   connection woken by the doorbell.  So an event taken from the outbox
%   is written before any later one.  Reading the outbox only under the
%   mutex is what keeps the order: a writer that took an event and then
%   waited for the mutex would write it after the newer ones the reply
%   took meanwhile.
%
%   The connection is ended (the context's `end` closure makes its
%   thread throw oro_connection_end(Why)) when the outbox is full (the
%   client fell too far behind), or when an event cannot be written
%   (the client left, or did not read for write_timeout seconds): then
%   the events still queued are dropped at once.
%
%   Context.subscribers is slot([]) until the first registration, then
%   slot([events(Subscriber, Outbox, Doorbell, Writer)]).

connection_subscriber(Context, Subscriber) :-
    Slot = Context.subscribers,
    arg(1, Slot, Subscribers),
    (   Subscribers = [events(Subscriber0, _, _, _)]
    ->  Subscriber = Subscriber0
    ;   setting(oro_server:event_queue, MaxQueue),
        message_queue_create(Outbox, [max_size(MaxQueue)]),
        message_queue_create(Doorbell, [max_size(1)]),
        End = Context.end,
        oro_subscriber_create(deliver_event(Outbox, Doorbell, End), Subscriber,
                              [in_watcher(true)]),
        Sink = sink(Context.out, Context.mutex, End, Outbox),
        thread_create(event_writer(Doorbell, Sink), Writer, []),
        nb_setarg(1, Slot, [events(Subscriber, Outbox, Doorbell, Writer)])
    ).

%   deliver_event(+Outbox, +Doorbell, +End, +Id, +Content): called by
%   the watcher thread for each firing; never waits.

deliver_event(Outbox, Doorbell, End, Id, Content) :-
    (   thread_send_message(Outbox, event(Id, Content), [timeout(0)])
    ->  ignore(thread_send_message(Doorbell, ring, [timeout(0)]))
    ;   debug(oro(server), 'Event ~w: the client fell behind', [Id]),
        call(End, events_overflow)
    ).

event_writer(Doorbell, Sink) :-
    catch(event_writer_loop(Doorbell, Sink), oro_event_writer_stop, true).

event_writer_loop(Doorbell, Sink) :-
    thread_get_message(Doorbell, ring),
    Sink = sink(Out, Mutex, End, Outbox),
    (   catch(with_mutex(Mutex, write_events(Outbox, Out)),
              error(Error, _),
              ( debug(oro(server), 'Events not delivered: ~q', [Error]),
                call(End, write_failed),
                fail
              ))
    ->  event_writer_loop(Doorbell, Sink)
    ;   true                                % the connection is ending
    ).

%   write_events(+Outbox, +Out): write the events the outbox holds, in
%   one write; nothing if the worker took them.

write_events(Outbox, Out) :-
    oro_drain_queue(Outbox, Events),
    (   Events == []
    ->  true
    ;   events_text(Events, Text),
        write(Out, Text),
        flush_output(Out)
    ).

events_text(Events, Text) :-
    with_output_to(string(Text),
                   ( current_output(S),
                     forall(member(event(Id, Content), Events),
                            ( event_content(Content, Value),
                              oro_write_event(S, Id, Value)
                            ))
                   )).

event_content([], void) :-
    !.
event_content(Values, list(Texts)) :-
    distinct_texts(Values, Texts).

:- meta_predicate
    oro_reply_with_events(+, 1).

%!  oro_reply_with_events(+Context, :Write) is semidet.
%
%   Write a reply to the connection of Context with call(Write, Stream),
%   followed by the events waiting for the connection, in one write:
%   first wait until the watcher thread has processed the changes the
%   calling thread made (oro_events_sync_sent/1), so that the events of
%   the request being answered are among them -- for reply_events_wait
%   seconds at most: events whose evaluation takes longer follow the
%   reply, written by the connection's event writer.  When Context's
%   `events_first` is `true` (the server's events_before_reply), the
%   events come first, then the reply, still in one write: a client
%   that reads as liboro does then never finds an event left over after
%   a reply (see README, Clients).  The caller holds the connection's
%   mutex.  Fails, writing nothing, if the connection has registered no
%   event.

oro_reply_with_events(Context, Write) :-
    arg(1, Context.subscribers, [events(_, Outbox, _, _)]),
    setting(reply_events_wait, Wait),
    ignore(oro_events_sync_sent(Wait)),
    oro_drain_queue(Outbox, Events),
    with_output_to(string(Reply),
                   ( current_output(S),
                     call(Write, S)
                   )),
    (   Events == []
    ->  Text = Reply
    ;   events_text(Events, EventsText),
        (   Context.events_first == true
        ->  string_concat(EventsText, Reply, Text)
        ;   string_concat(Reply, EventsText, Text)
        )
    ),
    Out = Context.out,
    write(Out, Text),
    flush_output(Out).

%!  oro_connection_events(+Context) is semidet.
%
%   True if the connection of Context has registered an event (its
%   replies are then written by oro_reply_with_events/2).

oro_connection_events(Context) :-
    arg(1, Context.subscribers, [_]).

%!  oro_connection_closed(+Context) is det.
%
%   Release what a connection holds: its event subscriber (and the
%   watchers only it subscribed to) and its event writer.  Events still
%   queued for the connection are dropped, and a write of events in
%   progress is interrupted: after an overflow it may be blocked on a
%   client that does not read, for up to write_timeout.  What such a
%   write left in the output buffer is not waited for either: the
%   output's timeout is lowered for the final close (every reply was
%   flushed when written).

oro_connection_closed(Context) :-
    catch(release_subscribers(Context),
          oro_connection_end(_),            % a late signal of its subscriber
          oro_connection_closed(Context)),
    catch(set_stream(Context.out, timeout(0.1)), _, true).

release_subscribers(Context) :-
    Slot = Context.subscribers,
    arg(1, Slot, Subscribers),
    forall(member(events(Subscriber, Outbox, Doorbell, Writer), Subscribers),
           ( catch(oro_subscriber_destroy(Subscriber), E,
                   ( E = oro_connection_end(_)
                   ->  throw(E)
                   ;   print_message(warning, E)
                   )),
             catch(thread_signal(Writer, throw(oro_event_writer_stop)), _, true),
             catch(thread_join(Writer, _), _, true),
             catch(message_queue_destroy(Outbox), _, true),
             catch(message_queue_destroy(Doorbell), _, true)
           )),
    nb_setarg(1, Slot, []).

		 /*******************************
		 *            HELPERS           *
		 *******************************/

statement_text(rdf(S, P, O), Text) :-
    oro_term_light_text(S, ST),
    oro_term_light_text(P, PT),
    oro_term_light_text(O, OT),
    atomic_list_concat([ST, PT, OT], ' ', Text).
